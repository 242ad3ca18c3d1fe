fn main() {
    println!("mountains");
}
