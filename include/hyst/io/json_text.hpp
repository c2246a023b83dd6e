#pragma once
//! \file
//! The one checked JSON parser of hyst. Every JSON text hyst reads (model files, fit options,
//! actuator configurations, `hyst info`) goes through parse_json_text().

#include <string_view>

#include <nlohmann/json.hpp>

namespace hyst::io {

//! Checks the structure of `text` without building a document: nesting no deeper than
//! limits::kMaxJsonDepth, no key twice in one object, UTF-8 or ASCII text without a NUL byte
//! (check_text_encoding(); nlohmann's parser would take a NUL for the end of the text and ignore
//! the rest). Throws hyst::Error
//! "SOURCE:LINE:COLUMN: ..." at the first violation, e.g. "m.json:3:14: duplicate key 'weights'
//! in 'params' (first at line 2, column 14)" or "m.json:1:257: JSON nesting deeper than 256
//! levels (the limit)". Does not judge the syntax otherwise (parse_json_text() does).
void check_json_text(std::string_view text, std::string_view source);

//! Parses `text` as JSON after check_json_text(). Syntax errors throw hyst::Error "SOURCE: not
//! valid JSON: parse error at line L, column C: ...", numbers beyond double "SOURCE: not valid
//! JSON: number overflow parsing '1e400' at line L, column C".
nlohmann::json parse_json_text(std::string_view text, std::string_view source);

}  // namespace hyst::io
