#pragma once
// Recognises text in UTF-16 or UTF-32, which hyst's text readers (UTF-8 and ASCII) do not read.

#include <string>
#include <string_view>

namespace hyst::io {

//! Throws hyst::Error "SOURCE: the file is UTF-16 (little-endian, with a byte order mark); hyst
//! reads UTF-8 or ASCII text (convert it, e.g. with iconv -f UTF-16 -t UTF-8)" when the text
//! starts with a UTF-16 or UTF-32 byte order mark, or, without one, when its first bytes show the
//! NUL pattern of ASCII characters in UTF-16 or UTF-32. Any other text holding a NUL byte is
//! refused too ("SOURCE:LINE:COLUMN: a NUL byte, ..."); returns for all other text.
void check_text_encoding(std::string_view text, std::string_view source);

//! True when `text` is well-formed UTF-8 (ASCII included).
bool is_utf8(std::string_view text);

//! `text` as UTF-8: unchanged when it is UTF-8 already, otherwise read as Latin-1 (ISO 8859-1),
//! which instrument software writes ("Am\xB2" for A m^2), and every byte above 0x7F converted.
//! For the header text and units of instrument files, whose data stay ASCII.
std::string utf8_from_latin1(std::string_view text);

}  // namespace hyst::io
