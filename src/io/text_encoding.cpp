#include "text_encoding.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst::io {
namespace {

struct Encoding {
  const char* name;    // "UTF-16"
  const char* endian;  // "little-endian"
  bool bom;
};

//! The wide encoding the text starts in, or a null name.
Encoding detect(std::string_view text) {
  const auto byte = [&](std::size_t k) -> int {
    return k < text.size() ? static_cast<unsigned char>(text[k]) : -1;
  };
  // Byte order marks; UTF-32LE's starts with UTF-16LE's, so it comes first.
  if (byte(0) == 0xFF && byte(1) == 0xFE && byte(2) == 0 && byte(3) == 0) {
    return {"UTF-32", "little-endian", true};
  }
  if (byte(0) == 0 && byte(1) == 0 && byte(2) == 0xFE && byte(3) == 0xFF) {
    return {"UTF-32", "big-endian", true};
  }
  if (byte(0) == 0xFF && byte(1) == 0xFE) return {"UTF-16", "little-endian", true};
  if (byte(0) == 0xFE && byte(1) == 0xFF) return {"UTF-16", "big-endian", true};
  // No mark: ASCII characters leave NUL bytes in a fixed pattern.
  const auto ascii = [](int b) { return b > 0 && b < 0x80; };
  if (text.size() >= 4) {
    if (ascii(byte(0)) && byte(1) == 0 && byte(2) == 0 && byte(3) == 0) {
      return {"UTF-32", "little-endian", false};
    }
    if (byte(0) == 0 && byte(1) == 0 && byte(2) == 0 && ascii(byte(3))) {
      return {"UTF-32", "big-endian", false};
    }
    if (ascii(byte(0)) && byte(1) == 0 && ascii(byte(2)) && byte(3) == 0) {
      return {"UTF-16", "little-endian", false};
    }
    if (byte(0) == 0 && ascii(byte(1)) && byte(2) == 0 && ascii(byte(3))) {
      return {"UTF-16", "big-endian", false};
    }
  }
  return {nullptr, nullptr, false};
}

}  // namespace

void check_text_encoding(std::string_view text, std::string_view source) {
  const Encoding encoding = detect(text);
  if (!encoding.name) {
    // Text never holds a NUL; refusing it here keeps every reader's verdict independent of where
    // in the file the NUL bytes happen to stand (the patterns above look at the start only).
    const auto nul = text.find('\0');
    if (nul == std::string_view::npos) return;
    const auto before = text.substr(0, nul);
    const auto line = 1 + std::count(before.begin(), before.end(), '\n');
    const auto line_start = before.rfind('\n');
    const auto column = line_start == std::string_view::npos ? nul + 1 : nul - line_start;
    throw Error(fmt::format(
        "{}:{}:{}: a NUL byte, which UTF-8 or ASCII text does not contain (a binary file?)", source,
        line, column));
  }
  throw Error(fmt::format(
      "{}: the file is {} ({}, {} byte order mark); hyst reads UTF-8 or ASCII text (convert it, "
      "e.g. with iconv -f {} -t UTF-8)",
      source, encoding.name, encoding.endian, encoding.bom ? "with a" : "without a",
      encoding.name));
}

bool is_utf8(std::string_view text) {
  std::size_t k = 0;
  while (k < text.size()) {
    const auto lead = static_cast<unsigned char>(text[k]);
    if (lead < 0x80) {
      ++k;
      continue;
    }
    // Continuation bytes after the lead byte, and the smallest code point of that length (an
    // overlong form is not UTF-8).
    std::size_t more = 0;
    std::uint32_t code = 0;
    std::uint32_t smallest = 0;
    if ((lead >> 5) == 0x6) {
      more = 1;
      code = lead & 0x1Fu;
      smallest = 0x80;
    } else if ((lead >> 4) == 0xE) {
      more = 2;
      code = lead & 0x0Fu;
      smallest = 0x800;
    } else if ((lead >> 3) == 0x1E) {
      more = 3;
      code = lead & 0x07u;
      smallest = 0x10000;
    } else {
      return false;
    }
    if (text.size() - k <= more) return false;
    for (std::size_t j = 1; j <= more; ++j) {
      const auto next = static_cast<unsigned char>(text[k + j]);
      if ((next >> 6) != 0x2) return false;
      code = (code << 6) | (next & 0x3Fu);
    }
    if (code < smallest || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return false;
    k += more + 1;
  }
  return true;
}

std::string utf8_from_latin1(std::string_view text) {
  if (is_utf8(text)) return std::string(text);
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x80) {
      out += c;
    } else {
      out += static_cast<char>(0xC0 | (byte >> 6));
      out += static_cast<char>(0x80 | (byte & 0x3F));
    }
  }
  return out;
}

}  // namespace hyst::io
