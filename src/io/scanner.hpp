// A cursor over a whole input text for the readers: white space, numbers by std::from_chars,
// and errors that name the line and column (computed only when an error is raised).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "pear/geometry.hpp"
#include "pear/io.hpp"

namespace pear::io::detail {

/// Which number spellings a format allows: JSON's exact grammar, or the looser one of WKT and
/// Triangle's files (a leading '+', "5." and ".5").
enum class NumberSyntax { json, loose };

/// A place in a text, counted from 1 (the column in bytes).
struct Location {
  std::size_t line, column;
};

class Scanner {
 public:
  /// Starts after a UTF-8 byte order mark, which some editors write at the start of a text.
  Scanner(std::string_view text, std::string_view name)
      : pos(text.starts_with("\xEF\xBB\xBF") ? 3 : 0), text_(text), name_(name) {}

  std::size_t pos;

  bool at_end() const { return pos >= text_.size(); }
  char peek() const { return pos < text_.size() ? text_[pos] : '\0'; }
  std::string_view text() const { return text_; }
  std::string_view name() const { return name_; }

  /// Skips spaces, tabs, CR and LF.
  void skip_space() {
    while (pos < text_.size()) {
      const char c = text_[pos];
      if (c != ' ' && c != '\n' && c != '\r' && c != '\t') break;
      ++pos;
    }
  }
  /// Skips white space and '#' comments that run to the end of the line.
  void skip_space_and_comments();
  /// For whitespace-separated formats: the token just read must end here; skips to the next.
  void end_token() {
    const char c = peek();
    if (!at_end() && c != ' ' && c != '\t' && c != '\n' && c != '\r' && c != '#')
      fail_expected(pos, "white space");
    skip_space_and_comments();
  }

  /// Consumes `c` or fails with "expected <what> but found ...".
  void expect(char c, const char* what) {
    if (peek() != c) fail_expected(pos, what);
    ++pos;
  }

  /// A finite double at pos; fails on bad syntax, NaN/inf spellings and out-of-range values.
  double number(NumberSyntax syntax);
  /// A non-negative integer token (loose syntax) that fits in size_t.
  std::size_t count(const char* what);
  /// An integer token, possibly negative.
  long long integer(const char* what);

  /// "expected <expected> but found <what is at offset>".
  [[noreturn]] void fail_expected(std::size_t offset, std::string_view expected) const;
  /// Any message at offset.
  [[noreturn]] void fail(std::size_t offset, std::string detail) const;
  /// The line and column of an offset.
  Location location(std::size_t offset) const;
  /// A short description of what is at offset: "end of file", "'x'", "'NaN'", "byte 0x00".
  std::string describe_found(std::size_t offset) const;

 private:
  std::size_t scan_number(NumberSyntax syntax) const;

  std::string_view text_;
  std::string name_;  // owned: callers may pass a temporary name
};

/// Drops a ring's closing point when it repeats the first; checks the ring has at least 3 points
/// unless the options keep small rings. `offset` is where the ring starts, for the error.
void finish_ring(Ring& ring, const Scanner& scanner, std::size_t offset,
                 const ReadOptions& options);

}  // namespace pear::io::detail
