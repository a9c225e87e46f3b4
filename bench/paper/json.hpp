// A small streaming JSON writer to stdout, enough for the experiments' flat records.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace bench {

class Json {
 public:
  Json& begin_array() { return open('['); }
  Json& end_array() { return close(']'); }
  Json& begin_object() { return open('{'); }
  Json& end_object() { return close('}'); }

  /// The key of the next value inside an object.
  Json& key(std::string_view name) {
    separate();
    write_string(name);
    std::fputc(':', stdout);
    after_key_ = true;
    return *this;
  }

  template <class Value>
  Json& field(std::string_view name, const Value& value) {
    key(name);
    return this->value(value);
  }

  Json& value(std::string_view text) {
    separate();
    write_string(text);
    return *this;
  }
  Json& value(const std::string& text) { return value(std::string_view(text)); }
  Json& value(const char* text) { return value(std::string_view(text)); }
  Json& value(bool flag) {
    separate();
    std::fputs(flag ? "true" : "false", stdout);
    return *this;
  }
  template <class Number>
  requires std::is_arithmetic_v<Number> Json& value(Number number) {
    separate();
    if constexpr (std::is_integral_v<Number>)
      std::fprintf(stdout, "%lld", static_cast<long long>(number));
    else if (std::isfinite(number))
      std::fprintf(stdout, "%.9g", static_cast<double>(number));
    else
      std::fputs("null", stdout);
    return *this;
  }

 private:
  Json& open(char bracket) {
    separate();
    std::fputc(bracket, stdout);
    first_.push_back(true);
    return *this;
  }
  Json& close(char bracket) {
    first_.pop_back();
    std::fputc(bracket, stdout);
    if (first_.empty()) std::fflush(stdout);
    return *this;
  }
  /// A comma before every value but the first of its array or object; none after a key.
  void separate() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (first_.empty()) return;
    if (!first_.back()) std::fputs(",\n", stdout);
    first_.back() = false;
  }
  static void write_string(std::string_view text) {
    std::fputc('"', stdout);
    for (const char c : text) {
      if (c == '"' || c == '\\') std::fputc('\\', stdout);
      if (static_cast<unsigned char>(c) >= 0x20) std::fputc(c, stdout);
    }
    std::fputc('"', stdout);
  }

  std::vector<bool> first_;
  bool after_key_ = false;
};

}  // namespace bench
