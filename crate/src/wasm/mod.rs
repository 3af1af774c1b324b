//! wasm boundary (being written)
