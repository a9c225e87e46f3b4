#include "scanner.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <limits>
#include <system_error>

namespace pear::io {

namespace {
std::string where(const std::string& file, std::size_t line, std::size_t column) {
  if (line == 0) return file + ": ";
  return file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
}
}  // namespace

ParseError::ParseError(std::string file, std::size_t line, std::size_t column, std::size_t offset,
                       std::string detail)
    : std::runtime_error(where(file, line, column) + detail),
      file_(std::move(file)),
      line_(line),
      column_(column),
      offset_(offset),
      detail_(std::move(detail)) {}

namespace detail {

namespace {
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}
bool is_word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-' ||
         c == '_';
}
}  // namespace

void Scanner::skip_space_and_comments() {
  for (;;) {
    skip_space();
    if (peek() != '#') return;
    while (pos < text_.size() && text_[pos] != '\n') ++pos;
  }
}

// Returns the end of a number spelled per `syntax` starting at pos, or pos if there is none.
std::size_t Scanner::scan_number(NumberSyntax syntax) const {
  std::size_t p = pos;
  const std::size_t n = text_.size();
  if (p < n && (text_[p] == '-' || (syntax == NumberSyntax::loose && text_[p] == '+'))) ++p;
  const std::size_t int_begin = p;
  while (p < n && is_digit(text_[p])) ++p;
  const std::size_t int_digits = p - int_begin;
  if (syntax == NumberSyntax::json) {
    if (int_digits == 0) return pos;
    if (int_digits > 1 && text_[int_begin] == '0') return pos;  // JSON forbids leading zeros
  }
  std::size_t frac_digits = 0;
  if (p < n && text_[p] == '.') {
    const std::size_t frac_begin = ++p;
    while (p < n && is_digit(text_[p])) ++p;
    frac_digits = p - frac_begin;
    if (syntax == NumberSyntax::json && frac_digits == 0) return pos;
  }
  if (int_digits + frac_digits == 0) return pos;
  if (p < n && (text_[p] == 'e' || text_[p] == 'E')) {
    ++p;
    if (p < n && (text_[p] == '+' || text_[p] == '-')) ++p;
    const std::size_t exp_begin = p;
    while (p < n && is_digit(text_[p])) ++p;
    if (p == exp_begin) return pos;
  }
  return p;
}

double Scanner::number(NumberSyntax syntax) {
  const std::size_t end = scan_number(syntax);
  if (end == pos) fail_expected(pos, "a number");
  const char* first = text_.data() + pos;
  // from_chars rejects a leading '+'; the loose syntax allows it.
  if (*first == '+') ++first;
  double value = 0;
  const auto [ptr, ec] = std::from_chars(first, text_.data() + end, value);
  if (ec == std::errc::result_out_of_range)
    fail_expected(pos, "a number within the range of a double");
  if (ec != std::errc() || ptr != text_.data() + end) fail_expected(pos, "a number");
  pos = end;
  return value;
}

std::size_t Scanner::count(const char* what) {
  const std::size_t at = pos;  // the error names the number, not what follows it
  const long long value = integer(what);
  if (value < 0) fail_expected(at, std::string("a non-negative ") + what);
  return static_cast<std::size_t>(value);
}

long long Scanner::integer(const char* what) {
  const char* first = text_.data() + pos;
  const char* last = text_.data() + text_.size();
  if (first != last && *first == '+') ++first;
  long long value = 0;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || (ptr != last && is_word_char(*ptr)))
    fail_expected(pos, std::string("an integer ") + what);
  pos = static_cast<std::size_t>(ptr - text_.data());
  return value;
}

std::string Scanner::describe_found(std::size_t offset) const {
  if (offset >= text_.size()) return "end of file";
  const unsigned char c = static_cast<unsigned char>(text_[offset]);
  if (c >= 0x80 || (c < 0x20 && c != '\n' && c != '\r' && c != '\t') || c == 0x7f) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "byte 0x%02x", c);
    return hex;
  }
  if (c == '\n' || c == '\r') return "end of line";
  if (c == '\t' || c == ' ') return "white space";
  std::size_t end = offset + 1;
  if (c == '"') {  // a whole short string
    while (end < text_.size() && end - offset < 32 && text_[end] != '"' && text_[end] != '\n')
      end += text_[end] == '\\' ? 2 : 1;
    if (end < text_.size() && text_[end] == '"') ++end;
  } else if (is_word_char(static_cast<char>(c))) {
    while (end < text_.size() && end - offset < 32 && is_word_char(text_[end])) ++end;
  }
  end = std::min(end, text_.size());
  std::string token = "'";
  token.append(text_.substr(offset, end - offset));
  token.push_back('\'');
  return token;
}

void Scanner::fail_expected(std::size_t offset, std::string_view expected) const {
  fail(offset, "expected " + std::string(expected) + " but found " + describe_found(offset));
}

Location Scanner::location(std::size_t offset) const {
  offset = std::min(offset, text_.size());
  const std::string_view before = text_.substr(0, offset);
  const std::size_t line =
      1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
  const std::size_t line_start = before.rfind('\n');
  return {line, line_start == std::string_view::npos ? offset + 1 : offset - line_start};
}

void Scanner::fail(std::size_t offset, std::string detail) const {
  offset = std::min(offset, text_.size());
  const Location where = location(offset);
  throw ParseError(std::string(name_), where.line, where.column, offset, std::move(detail));
}

void finish_ring(Ring& ring, const Scanner& scanner, std::size_t offset,
                 const ReadOptions& options) {
  if (ring.size() >= 2 && ring.front() == ring.back()) ring.pop_back();
  if (ring.size() < 3 && !options.keep_small_rings)
    scanner.fail(offset,
                 "expected a ring of at least 3 points (besides a closing point) but found " +
                     std::to_string(ring.size()) + (ring.size() == 1 ? " point" : " points"));
}

}  // namespace detail
}  // namespace pear::io
