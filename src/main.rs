fn main() {
    println!("geocert");
}
