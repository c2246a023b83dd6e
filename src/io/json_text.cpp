#include "hyst/io/json_text.hpp"

#include <algorithm>
#include <cstddef>
#include <new>
#include <string>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/io/limits.hpp"
#include "text_encoding.hpp"

namespace hyst::io {
namespace {

struct Position {
  std::size_t line = 1;
  std::size_t column = 1;
};

//! One open array or object of the scan.
struct Frame {
  bool object = false;
  bool expect_key = false;
  std::string path;  // "params.weights[]"-like name of this value, for messages
  std::unordered_map<std::string, Position> keys;
};

//! A key or path for a one-line message: cut after 60 bytes, control characters (a decoded
//! "\n" or "\u0000") shown as '?'.
std::string shown(std::string_view key) {
  std::string text(key.substr(0, 60));
  for (char& c : text) {
    if (static_cast<unsigned char>(c) < 0x20) c = '?';
  }
  return key.size() > 60 ? text + "..." : text;
}

//! The key a string token stands for: escapes decoded when it has any ("\u0061" is "a").
std::string decode_key(std::string_view token) {
  if (token.find('\\') == std::string_view::npos) {
    return std::string(token.substr(1, token.size() - 2));
  }
  const auto decoded = nlohmann::json::parse(token, nullptr, /*allow_exceptions=*/false);
  if (decoded.is_string()) return decoded.get<std::string>();
  return std::string(token.substr(1, token.size() - 2));
}

//! " at line L, column C" for nlohmann's "number overflow parsing '1e400'", which has no position:
//! the first occurrence of the number in the text. Empty for other messages.
std::string overflow_position(const std::string& message, std::string_view text) {
  static constexpr std::string_view marker = "number overflow parsing '";
  const auto start = message.find(marker);
  if (start == std::string::npos) return {};
  const auto end = message.find('\'', start + marker.size());
  if (end == std::string::npos) return {};
  const auto number =
      std::string_view(message).substr(start + marker.size(), end - start - marker.size());
  const auto at = text.find(number);
  if (number.empty() || at == std::string_view::npos) return {};
  const auto before = text.substr(0, at);
  const auto line = 1 + std::count(before.begin(), before.end(), '\n');
  const auto line_start = before.rfind('\n');
  const auto column = line_start == std::string_view::npos ? at + 1 : at - line_start;
  return fmt::format(" at line {}, column {}", line, column);
}

}  // namespace

void check_json_text(std::string_view text, std::string_view source) {
  // nlohmann's parser takes a NUL byte for the end of the input and ignores what follows it;
  // the encoding check refuses one wherever it stands.
  check_text_encoding(text, source);
  std::vector<Frame> stack;
  Position at;
  std::string pending_key;  // the last key read, names the value that follows it
  std::size_t i = 0;
  const auto advance = [&](char c) {
    if (c == '\n') {
      ++at.line;
      at.column = 1;
    } else {
      ++at.column;
    }
  };
  while (i < text.size()) {
    const char c = text[i];
    if (c == '"') {
      const Position start = at;
      const std::size_t begin = i;
      advance(c);
      ++i;
      bool closed = false;
      while (i < text.size()) {
        const char d = text[i];
        advance(d);
        ++i;
        if (d == '\\' && i < text.size()) {
          advance(text[i]);
          ++i;
        } else if (d == '"') {
          closed = true;
          break;
        }
      }
      if (!closed) return;  // an unterminated string: the parser reports it
      if (!stack.empty() && stack.back().object && stack.back().expect_key) {
        auto& frame = stack.back();
        frame.expect_key = false;
        std::string key = decode_key(text.substr(begin, i - begin));
        const auto [first, inserted] = frame.keys.try_emplace(key, start);
        if (!inserted) {
          throw Error(fmt::format("{}:{}:{}: duplicate key '{}'{} (first at line {}, column {})",
                                  source, start.line, start.column, shown(key),
                                  frame.path.empty() ? "" : " in '" + shown(frame.path) + "'",
                                  first->second.line, first->second.column));
        }
        pending_key = std::move(key);
      }
      continue;
    }
    if (c == '{' || c == '[') {
      if (stack.size() >= limits::kMaxJsonDepth) {
        throw Error(fmt::format(
            "{}:{}:{}: JSON nesting deeper than {} levels (the limit of hyst's JSON reader)",
            source, at.line, at.column, limits::kMaxJsonDepth));
      }
      std::string path;
      if (!stack.empty()) {
        const auto& parent = stack.back();
        if (parent.object) {
          path = parent.path.empty() ? pending_key : parent.path + "." + pending_key;
        } else {
          path = parent.path + "[]";
        }
        if (path.size() > 200) path = path.substr(0, 200);
      }
      stack.push_back(Frame{c == '{', c == '{', std::move(path), {}});
    } else if (c == '}' || c == ']') {
      if (!stack.empty()) stack.pop_back();
    } else if (c == ',') {
      if (!stack.empty() && stack.back().object) stack.back().expect_key = true;
    }
    advance(c);
    ++i;
  }
}

nlohmann::json parse_json_text(std::string_view text, std::string_view source) {
  check_json_text(text, source);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& error) {
    // Syntax errors (parse_error) and numbers beyond double (out_of_range 406, "number overflow
    // parsing '1e400'"). The library's message reads "[json.exception.parse_error.101] parse
    // error at line 3, column 5: ..."; keep the part after the tag.
    std::string message = error.what();
    if (const auto tag_end = message.find("] "); tag_end != std::string::npos) {
      message = message.substr(tag_end + 2);
    }
    throw Error(
        fmt::format("{}: not valid JSON: {}{}", source, message, overflow_position(message, text)));
  } catch (const std::bad_alloc&) {
    throw Error(fmt::format("{}: out of memory parsing {} bytes of JSON", source, text.size()));
  }
}

}  // namespace hyst::io
