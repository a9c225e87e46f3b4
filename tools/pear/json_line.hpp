// One JSON object on one line, for --stats and `pear stats --json`.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

namespace pear::cli {

class JsonLine {
 public:
  JsonLine& add(std::string_view key, std::string_view value) {
    start(key);
    text_ += '"';
    for (const char c : value) {
      if (c == '"' || c == '\\') {
        text_ += '\\';
        text_ += c;
      } else if (static_cast<unsigned char>(c) < 0x20) {
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
        text_ += escaped;
      } else {
        text_ += c;
      }
    }
    text_ += '"';
    return *this;
  }
  JsonLine& add(std::string_view key, const char* value) {
    return add(key, std::string_view(value));
  }
  JsonLine& add(std::string_view key, bool value) {
    start(key);
    text_ += value ? "true" : "false";
    return *this;
  }
  JsonLine& add(std::string_view key, std::size_t value) {
    start(key);
    text_ += std::to_string(value);
    return *this;
  }
  /// Shortest round-trip form; null for NaN or infinity, which JSON cannot spell.
  JsonLine& add(std::string_view key, double value) {
    start(key);
    if (!std::isfinite(value)) {
      text_ += "null";
      return *this;
    }
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    text_.append(buffer, end);
    return *this;
  }
  /// A nested object.
  JsonLine& add(std::string_view key, const JsonLine& object) {
    start(key);
    text_ += object.str();
    return *this;
  }
  std::string str() const { return text_.empty() ? "{}" : text_ + "}"; }

 private:
  void start(std::string_view key) {
    text_ += text_.empty() ? "{\"" : ",\"";
    text_ += key;
    text_ += "\":";
  }
  std::string text_;
};

}  // namespace pear::cli
