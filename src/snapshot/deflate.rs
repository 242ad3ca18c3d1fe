//! Deflate (RFC 1951) for a PNG's rows, a part at a time, so that parts
//! can be packed on several threads and joined into one zlib stream.
//!
//! A part is one block whose Huffman code is made for its own bytes,
//! closed by an empty stored block (zlib's "sync flush"): it ends on a
//! byte, and the next part's block can follow it as it is. Only two kinds
//! of token are written, for speed (fdeflate's idea): literal bytes, and
//! runs of whole words of zero bytes (a zero, then copies of the byte
//! before). Rows filtered against the row above are mostly small numbers,
//! and long runs of zeros where the picture is flat.

use super::huffman;

/// The longest copy deflate writes.
const MAX_COPY: u32 = 258;

/// Symbols of the literal and length alphabet (RFC 1951, 3.2.5).
const SYMBOLS: usize = 286;
/// The end of a block.
const END: usize = 256;

/// The shortest copy of each length symbol (257 on), and its extra bits.
const COPY_BASE: [u16; 29] = [
    3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131,
    163, 195, 227, 258,
];
const COPY_EXTRA: [u8; 29] = [
    0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0,
];

/// The length symbol's index (into [`COPY_BASE`]) of each copy length.
const COPY_SYMBOL: [u8; MAX_COPY as usize + 1] = {
    let mut table = [0u8; MAX_COPY as usize + 1];
    let mut len = 3;
    while len <= MAX_COPY as usize {
        let mut i = 0;
        while i + 1 < COPY_BASE.len() && COPY_BASE[i + 1] as usize <= len {
            i += 1;
        }
        table[len] = i as u8;
        len += 1;
    }
    table
};

/// The order in which a block's header gives the code lengths' own code.
const LENGTH_ORDER: [usize; 19] = [
    16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15,
];

/// The longest code of the literals and lengths, and of the code lengths.
const LONGEST: u8 = 15;
const LONGEST_LENGTH_CODE: u8 = 7;

/// Appends to `out` the deflate blocks of `data`, ending on a byte with
/// an empty stored block, so that more blocks may follow. None of them is
/// the stream's last: [`LAST_BLOCK`] closes a stream.
pub(crate) fn part(data: &[u8], out: &mut Vec<u8>) {
    let lengths = huffman::lengths(&sampled_counts(data), LONGEST);
    let codes = huffman::codes(&lengths);
    let mut writer = Writer {
        bits: Bits::new(out),
        lengths: std::array::from_fn(|i| lengths[i]),
        codes: std::array::from_fn(|i| codes[i]),
    };
    // Room for most parts' blocks at once.
    writer.bits.out.reserve(data.len() + data.len() / 8 + 1024);
    // Not the last block; dynamic Huffman codes.
    writer.bits.put(0b100, 3);
    header(&mut writer.bits, &lengths);
    tokens(data, &mut writer);
    writer.symbol(END);
    // The empty stored block: its header, then its length and the
    // length's complement on the next byte.
    writer.bits.put(0, 3);
    writer.bits.align();
    writer.bits.out.extend_from_slice(&[0, 0, 0xff, 0xff]);
}

/// Data up to this long is counted whole; longer, in [`SAMPLES`] pieces
/// spread over it, each a [`SAMPLE_SHARE`]th of it (a picture's bytes are
/// much alike along a part: a quarter of them makes nearly the same code,
/// for a third of the time the counting took).
const COUNT_WHOLE: usize = 1 << 16;
const SAMPLES: usize = 4;
const SAMPLE_SHARE: usize = 16;

/// How often each literal and length symbol is written for `data`, from
/// samples of it if it is long: every symbol is counted at least once,
/// so that a byte or a run the samples missed still has a code.
fn sampled_counts(data: &[u8]) -> [u32; SYMBOLS] {
    let mut counts = Counts::new();
    if data.len() <= COUNT_WHOLE {
        tokens(data, &mut counts);
    } else {
        let (step, len) = (data.len() / SAMPLES, data.len() / SAMPLE_SHARE);
        for k in 0..SAMPLES {
            tokens(&data[k * step..k * step + len], &mut counts);
        }
    }
    counts.with_end().map(|c| c.max(1))
}

/// A last, empty block (fixed codes, at once its end): it closes a stream
/// of [`part`]s.
pub(crate) const LAST_BLOCK: [u8; 2] = [0x03, 0x00];

/// Where [`tokens`] sends what it finds.
trait Sink {
    /// `n` (eight or more) zero bytes.
    fn zeros(&mut self, n: u32);

    /// Bytes as they are.
    fn literals(&mut self, bytes: &[u8]);
}

/// Sends `data` to `sink` as literals and runs of zeros, eight bytes at a
/// time: words of eight zero bytes in a row make a run, every other byte
/// is a literal (a zero among others is one of the cheapest codes, and a
/// word whose bytes all go one way costs no guess of the processor's).
#[inline(always)]
fn tokens(data: &[u8], sink: &mut impl Sink) {
    let mut run = 0u32;
    let mut words = data.chunks_exact(8);
    for word in &mut words {
        if word == [0; 8] {
            run += 8;
            continue;
        }
        if run > 0 {
            sink.zeros(run);
            run = 0;
        }
        sink.literals(word);
    }
    if run > 0 {
        sink.zeros(run);
    }
    sink.literals(words.remainder());
}

/// How often each literal and length symbol is written: the literals of
/// a row of bytes counted in four tables in turn, so that a run of one
/// byte does not wait on its own count.
struct Counts {
    literals: [[u32; 256]; 4],
    symbols: [u32; SYMBOLS],
}

impl Counts {
    fn new() -> Self {
        Counts {
            literals: [[0; 256]; 4],
            symbols: [0; SYMBOLS],
        }
    }

    /// Every symbol's count, with the block's end counted once.
    fn with_end(&self) -> [u32; SYMBOLS] {
        let mut all = self.symbols;
        for table in &self.literals {
            for (c, t) in all.iter_mut().zip(table) {
                *c += t;
            }
        }
        all[END] += 1;
        all
    }
}

impl Sink for Counts {
    #[inline(always)]
    fn zeros(&mut self, n: u32) {
        let left = copies(n - 1, |len| {
            self.symbols[257 + COPY_SYMBOL[len as usize] as usize] += 1;
        });
        self.symbols[0] += 1 + left;
    }

    #[inline(always)]
    fn literals(&mut self, bytes: &[u8]) {
        for (i, &b) in bytes.iter().enumerate() {
            self.literals[i % 4][b as usize] += 1;
        }
    }
}

/// Calls `copy(len)` for each copy of a run of `n` bytes (each 3 to 258
/// long), and returns the bytes left over (at most two, too few for a
/// copy: literals).
#[inline(always)]
fn copies(mut n: u32, mut copy: impl FnMut(u32)) -> u32 {
    while n >= 3 {
        let mut len = n.min(MAX_COPY);
        // Leave no tail of one or two bytes after a longest copy.
        if (1..3).contains(&(n - len)) {
            len -= 3;
        }
        copy(len);
        n -= len;
    }
    n
}

/// A block's bits, with the code it writes its symbols in.
struct Writer<'a> {
    bits: Bits<'a>,
    lengths: [u8; SYMBOLS],
    codes: [u16; SYMBOLS],
}

impl Writer<'_> {
    /// Writes the code of `symbol`.
    #[inline(always)]
    fn symbol(&mut self, symbol: usize) {
        self.bits.put(
            u64::from(self.codes[symbol]),
            u32::from(self.lengths[symbol]),
        );
    }
}

impl Sink for Writer<'_> {
    #[inline(always)]
    fn zeros(&mut self, n: u32) {
        self.symbol(0);
        let left = copies(n - 1, |len| {
            let i = COPY_SYMBOL[len as usize] as usize;
            self.symbol(257 + i);
            let extra = u32::from(COPY_EXTRA[i]);
            // The copy's extra bits, then its distance: code 0 of a
            // one-code distance alphabet (one bit, 0), the byte before.
            self.bits
                .put(u64::from(len - u32::from(COPY_BASE[i])), extra + 1);
        });
        for _ in 0..left {
            self.symbol(0);
        }
    }

    /// Four codes of at most 15 bits a write.
    #[inline(always)]
    fn literals(&mut self, bytes: &[u8]) {
        for four in bytes.chunks(4) {
            let (mut bits, mut n) = (0u64, 0u32);
            for &b in four {
                bits |= u64::from(self.codes[b as usize]) << n;
                n += u32::from(self.lengths[b as usize]);
            }
            self.bits.put(bits, n);
        }
    }
}

/// Writes a dynamic block's header after its first three bits: how many
/// codes of each alphabet, the code lengths' own code, and the literal
/// and length code's lengths (`lengths`) and the distance code's (one
/// code of one bit), run-length coded.
fn header(bits: &mut Bits, lengths: &[u8]) {
    let literals = (257..=SYMBOLS)
        .rev()
        .find(|&n| lengths[n - 1] > 0)
        .unwrap_or(257);
    let mut all = lengths[..literals].to_vec();
    all.push(1);
    let runs = run_lengths(&all);
    let mut counts = [0u32; 19];
    for &(symbol, _) in &runs {
        counts[symbol as usize] += 1;
    }
    let code_lengths = huffman::lengths(&counts, LONGEST_LENGTH_CODE);
    let codes = huffman::codes(&code_lengths);
    let sent = (4..=19)
        .rev()
        .find(|&n| code_lengths[LENGTH_ORDER[n - 1]] > 0)
        .unwrap_or(4);
    bits.put((literals - 257) as u64, 5);
    bits.put(0, 5);
    bits.put((sent - 4) as u64, 4);
    for &symbol in &LENGTH_ORDER[..sent] {
        bits.put(u64::from(code_lengths[symbol]), 3);
    }
    for (symbol, extra) in runs {
        let s = symbol as usize;
        bits.put(u64::from(codes[s]), u32::from(code_lengths[s]));
        match symbol {
            16 => bits.put(u64::from(extra), 2),
            17 => bits.put(u64::from(extra), 3),
            18 => bits.put(u64::from(extra), 7),
            _ => {}
        }
    }
}

/// `lengths` as the code-length alphabet's symbols and their extra bits:
/// 16 repeats the length before 3-6 times, 17 writes 3-10 zeros, 18
/// writes 11-138.
fn run_lengths(lengths: &[u8]) -> Vec<(u8, u8)> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < lengths.len() {
        let l = lengths[i];
        let n = lengths[i..].iter().take_while(|&&x| x == l).count();
        let mut left = n;
        if l == 0 {
            while left >= 11 {
                let k = left.min(138);
                out.push((18, (k - 11) as u8));
                left -= k;
            }
            if left >= 3 {
                out.push((17, (left - 3) as u8));
                left = 0;
            }
        } else {
            out.push((l, 0));
            left -= 1;
            while left >= 3 {
                let k = left.min(6);
                out.push((16, (k - 3) as u8));
                left -= k;
            }
        }
        out.extend(std::iter::repeat_n((l, 0), left));
        i += n;
    }
    out
}

/// Bits written the lowest first, 64 at a time.
struct Bits<'a> {
    out: &'a mut Vec<u8>,
    held: u64,
    /// Bits held, under 64.
    count: u32,
}

impl<'a> Bits<'a> {
    fn new(out: &'a mut Vec<u8>) -> Self {
        Bits {
            out,
            held: 0,
            count: 0,
        }
    }

    /// Writes the `n` (at most 64) low bits of `bits`.
    #[inline(always)]
    fn put(&mut self, bits: u64, n: u32) {
        debug_assert!(n <= 64 && bits.checked_shr(n).unwrap_or(0) == 0);
        self.held |= bits << self.count;
        self.count += n;
        if self.count >= 64 {
            self.out.extend_from_slice(&self.held.to_le_bytes());
            self.count -= 64;
            // The bits that did not fit.
            self.held = bits.checked_shr(n - self.count).unwrap_or(0);
        }
    }

    /// Writes the bits held, up to the next byte.
    fn align(&mut self) {
        let bytes = self.count.div_ceil(8) as usize;
        self.out
            .extend_from_slice(&self.held.to_le_bytes()[..bytes]);
        (self.held, self.count) = (0, 0);
    }
}

/// The Adler-32 of `data` (zlib's checksum).
pub(crate) fn adler(data: &[u8]) -> u32 {
    let mut sum = simd_adler32::Adler32::new();
    sum.write(data);
    sum.finish()
}

/// The Adler-32 of two pieces of data one after the other, from each
/// one's and the second's length (zlib's adler32_combine): parts packed
/// apart make one stream.
pub(crate) fn adler_joined(first: u32, second: u32, second_len: u64) -> u32 {
    const BASE: u64 = 65521;
    let rem = second_len % BASE;
    let (a1, b1) = (u64::from(first & 0xffff), u64::from(first >> 16));
    let (a2, b2) = (u64::from(second & 0xffff), u64::from(second >> 16));
    let a = (a1 + a2 + BASE - 1) % BASE;
    let b = (rem * a1 % BASE + b1 + b2 + BASE - rem) % BASE;
    (a | b << 16) as u32
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Read;

    /// `parts` packed apart and joined into a zlib stream.
    fn zlib(parts: &[&[u8]]) -> Vec<u8> {
        let mut out = vec![0x78, 0x01];
        let mut sum = 1;
        for p in parts {
            part(p, &mut out);
            sum = adler_joined(sum, adler(p), p.len() as u64);
        }
        out.extend_from_slice(&LAST_BLOCK);
        out.extend_from_slice(&sum.to_be_bytes());
        out
    }

    /// What an independent inflater (miniz_oxide, which checks the
    /// Adler-32) reads of `stream`.
    fn inflated(stream: &[u8]) -> Vec<u8> {
        let mut got = Vec::new();
        flate2::read::ZlibDecoder::new(stream)
            .read_to_end(&mut got)
            .expect("a valid zlib stream");
        got
    }

    /// Bytes like a filtered picture's: small steps, runs of zeros of
    /// every length at every offset, now and then anything.
    fn picture_like(n: usize, seed: u64) -> Vec<u8> {
        let mut x = seed | 1;
        let mut next = move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let mut out = Vec::with_capacity(n);
        while out.len() < n {
            let r = next();
            match r % 4 {
                0 => out.extend(std::iter::repeat_n(0, (r >> 8) as usize % 600)),
                1 => out.push((r >> 8) as u8),
                _ => out.push(((r >> 8) % 5) as u8 ^ if r & 1 << 40 == 0 { 0 } else { 0xff }),
            }
        }
        out.truncate(n);
        out
    }

    #[test]
    fn parts_joined_inflate_to_the_data_whatever_the_cut() {
        for seed in 1..6 {
            let data = picture_like(40_000, seed);
            for cut in [0, 1, 7, 8, 9, 4095, 20_000, 39_999, 40_000] {
                let (a, b) = data.split_at(cut);
                assert_eq!(inflated(&zlib(&[a, b])), data, "seed {seed} cut {cut}");
            }
        }
    }

    #[test]
    fn runs_of_every_length_round_trip() {
        for n in 0..1100 {
            for lead in [0, 3] {
                let mut data = vec![9u8; lead];
                data.extend(std::iter::repeat_n(0, n));
                data.push(5);
                assert_eq!(inflated(&zlib(&[&data])), data, "run {n} after {lead}");
            }
        }
        for data in [vec![], vec![0], vec![0; 7], vec![1; 3], (0..=255).collect()] {
            assert_eq!(inflated(&zlib(&[&data])), data);
        }
    }

    #[test]
    fn a_byte_and_a_run_the_samples_miss_still_have_codes() {
        let mut data = vec![1u8; 1 << 20];
        // Between the first two samples, which see only ones.
        data[(1 << 18) - 5] = 0x77;
        data[(1 << 18) + 8..(1 << 18) + 8 + 300].fill(0);
        assert!(data.len() > COUNT_WHOLE);
        assert_eq!(inflated(&zlib(&[&data])), data);
    }

    #[test]
    fn a_flat_picture_packs_small() {
        let data = vec![0u8; 1 << 20];
        let stream = zlib(&[&data]);
        assert!(stream.len() < 1 << 13, "{} bytes", stream.len());
        assert_eq!(inflated(&stream), data);
    }

    #[test]
    fn a_wrong_checksum_is_caught_by_the_inflater_these_tests_use() {
        let data = picture_like(5000, 3);
        let mut stream = zlib(&[&data[..100], &data[100..]]);
        let last = stream.len() - 1;
        stream[last] ^= 1;
        let mut sink = Vec::new();
        assert!(
            flate2::read::ZlibDecoder::new(&stream[..])
                .read_to_end(&mut sink)
                .is_err()
        );
    }

    #[test]
    fn adler_of_joined_pieces_is_the_adler_of_the_whole() {
        let data = picture_like(200_000, 9);
        for cut in [0, 1, 65_520, 65_521, 65_522, 131_042, 199_999, 200_000] {
            let (a, b) = data.split_at(cut);
            let joined = adler_joined(adler(a), adler(b), b.len() as u64);
            assert_eq!(joined, adler(&data), "cut {cut}");
        }
    }

    #[test]
    fn copy_symbols_follow_rfc_1951s_table() {
        for (len, want) in [
            (3, 0),
            (10, 7),
            (11, 8),
            (12, 8),
            (13, 9),
            (257, 27),
            (258, 28),
        ] {
            assert_eq!(COPY_SYMBOL[len], want, "length {len}");
        }
    }
}
