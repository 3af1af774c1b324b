//! Helpers shared by the wasm boundary test files (`wasm-pack test --node`; each includes this
//! module and uses what it needs).
#![allow(dead_code)]

use wasm_bindgen::{JsCast, JsValue};

/// The message of a JS error, after checking that it really is an `Error` object.
pub fn error_message(error: wasm_bindgen::JsError) -> String {
    let value = JsValue::from(error);
    let error = value.dyn_ref::<js_sys::Error>().expect("a JS Error object");
    String::from(error.message())
}

/// A plain JS value (objects, arrays, numbers) as JSON, to read in assertions.
pub fn json(value: JsValue) -> serde_json::Value {
    serde_wasm_bindgen::from_value(value).expect("plain data")
}
