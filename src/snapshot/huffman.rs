//! Huffman codes as deflate writes them (RFC 1951, 3.2.2): the lengths
//! of a code made for the counts of its symbols, held to deflate's
//! longest, and the canonical codes those lengths give.

/// The code lengths of a complete prefix code for symbols seen `counts`
/// times (0 for a symbol never seen), none longer than `limit` bits.
///
/// At least two symbols get a code: a code of one symbol is incomplete,
/// and inflaters refuse that for most of deflate's alphabets; a lone
/// symbol gets a partner of its own (the next or the one before).
pub(crate) fn lengths(counts: &[u32], limit: u8) -> Vec<u8> {
    let mut counts = counts.to_vec();
    if counts.iter().filter(|&&c| c > 0).count() < 2 {
        let lone = counts.iter().position(|&c| c > 0).unwrap_or(0);
        let partner = if lone + 1 < counts.len() {
            lone + 1
        } else {
            lone - 1
        };
        counts[lone] = counts[lone].max(1);
        counts[partner] = 1;
    }
    loop {
        let lengths = unlimited(&counts);
        if lengths.iter().all(|&l| l <= limit) {
            return lengths;
        }
        // Flatter counts make a shallower tree; a rare symbol's code is
        // a bit longer than it might be, which costs next to nothing.
        for c in counts.iter_mut().filter(|c| **c > 0) {
            *c = (*c >> 1) | 1;
        }
    }
}

/// The lengths of a Huffman code for `counts` (at least two non-zero),
/// however long: two queues, the leaves by count and the joined nodes in
/// the order they were made (so already by weight).
fn unlimited(counts: &[u32]) -> Vec<u8> {
    let mut leaves: Vec<(u64, usize)> = counts
        .iter()
        .enumerate()
        .filter(|(_, c)| **c > 0)
        .map(|(s, &c)| (u64::from(c), s))
        .collect();
    leaves.sort_unstable();
    let n = leaves.len();
    // Node i < n is leaf i; node n + j is the j-th joined node.
    let mut weight: Vec<u64> = leaves.iter().map(|l| l.0).collect();
    let mut parent = vec![0usize; 2 * n - 1];
    let (mut next_leaf, mut next_joined) = (0, n);
    for made in n..2 * n - 1 {
        let mut lightest = || {
            let leaf = next_leaf < n;
            let joined = next_joined < made;
            let take_leaf = leaf && (!joined || weight[next_leaf] <= weight[next_joined]);
            let node = if take_leaf { next_leaf } else { next_joined };
            if take_leaf {
                next_leaf += 1;
            } else {
                next_joined += 1;
            }
            node
        };
        let (a, b) = (lightest(), lightest());
        weight.push(weight[a] + weight[b]);
        (parent[a], parent[b]) = (made, made);
    }
    // The root is the last node made; a node lies one deeper than its
    // parent, which was made after it.
    let mut depth = vec![0u8; 2 * n - 1];
    for node in (0..2 * n - 2).rev() {
        depth[node] = depth[parent[node]] + 1;
    }
    let mut lengths = vec![0u8; counts.len()];
    for (i, &(_, symbol)) in leaves.iter().enumerate() {
        lengths[symbol] = depth[i];
    }
    lengths
}

/// The canonical codes of `lengths`, each bit-reversed as deflate writes
/// a code (its first bit in the lowest bit of the stream's next byte).
pub(crate) fn codes(lengths: &[u8]) -> Vec<u16> {
    let longest = lengths.iter().copied().max().unwrap_or(0) as usize;
    let mut of_length = vec![0u16; longest + 1];
    for &l in lengths.iter().filter(|&&l| l > 0) {
        of_length[l as usize] += 1;
    }
    let mut next = vec![0u16; longest + 1];
    let mut code = 0u16;
    for bits in 1..=longest {
        code = (code + of_length[bits - 1]) << 1;
        next[bits] = code;
    }
    lengths
        .iter()
        .map(|&l| {
            if l == 0 {
                return 0;
            }
            let c = next[l as usize];
            next[l as usize] += 1;
            c.reverse_bits() >> (16 - l)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Kraft's sum in units of 2^-limit: exactly 2^limit for a complete code.
    fn kraft(lengths: &[u8], limit: u8) -> u64 {
        lengths
            .iter()
            .filter(|&&l| l > 0)
            .map(|&l| 1u64 << (limit - l))
            .sum()
    }

    #[test]
    fn a_code_is_complete_and_gives_the_common_symbols_the_short_codes() {
        let counts = [40, 0, 20, 10, 5, 5, 1, 0, 1];
        let l = lengths(&counts, 15);
        assert_eq!(kraft(&l, 15), 1 << 15, "{l:?}");
        assert_eq!((l[1], l[7]), (0, 0), "unseen symbols get no code");
        assert!(l[0] < l[3] && l[3] < l[8], "{l:?}");
    }

    #[test]
    fn a_skewed_alphabet_is_held_to_the_limit_and_stays_complete() {
        // Fibonacci counts make a Huffman tree as deep as it has symbols.
        let mut counts = vec![1u32, 1];
        while counts.len() < 30 {
            let n = counts.len();
            counts.push(counts[n - 1] + counts[n - 2]);
        }
        assert!(unlimited(&counts).iter().any(|&l| l > 15));
        for limit in [7, 15] {
            let l = lengths(&counts, limit);
            assert!(l.iter().all(|&x| (1..=limit).contains(&x)), "{l:?}");
            assert_eq!(kraft(&l, limit), 1 << limit, "{l:?}");
        }
    }

    #[test]
    fn a_lone_symbol_gets_a_partner() {
        for (counts, want) in [
            (vec![0, 0, 7, 0], vec![0, 0, 1, 1]),
            (vec![0, 0, 0, 7], vec![0, 0, 1, 1]),
            (vec![0, 0, 0, 0], vec![1, 1, 0, 0]),
        ] {
            assert_eq!(lengths(&counts, 7), want, "{counts:?}");
        }
    }

    #[test]
    fn canonical_codes_follow_rfc_1951s_example() {
        // RFC 1951, 3.2.2: lengths (3, 3, 3, 3, 3, 2, 4, 4) give
        // 010, 011, 100, 101, 110, 00, 1110, 1111.
        let want = [0b010, 0b011, 0b100, 0b101, 0b110, 0b00, 0b1110, 0b1111];
        let lengths = [3, 3, 3, 3, 3, 2, 4, 4];
        let got = codes(&lengths);
        for ((&g, &w), &l) in got.iter().zip(&want).zip(&lengths) {
            assert_eq!(g, (w as u16).reverse_bits() >> (16 - l));
        }
    }
}
