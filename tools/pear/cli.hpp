// The pear command-line tool: what its subcommands share.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "pear/pear.hpp"

namespace pear::cli {

/// Exit codes, as `pear --help` documents them.
enum Exit : int { success = 0, bad_input = 1, usage = 2, invalid_result = 3 };

/// A mistake on the command line: printed with a hint to --help, exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Command-line arguments of one subcommand, read front to back.
/// Options are `--name value`, `--name=value`, `-o value` or flags; `--` ends them;
/// a lone `-` is a positional argument (stdin).
class Args {
 public:
  explicit Args(std::span<const std::string_view> args) : args_(args) {}

  /// The next option name ("--threads", "-o"), or nullopt when the next argument is positional
  /// (it is then moved to positionals()).
  std::optional<std::string_view> next_option();
  /// The value of the option just returned by next_option.
  std::string_view value();
  /// The option's value as an integer in [min, max].
  std::uint64_t integer(std::uint64_t min, std::uint64_t max);
  /// The option's value as a positive size in bytes: digits, optionally followed by K, M or G
  /// (1024-based).
  std::size_t byte_size();
  /// Fails if the option just returned came with `=value`.
  void no_value();
  bool done() const { return index_ >= args_.size(); }
  const std::vector<std::string_view>& positionals() const { return positionals_; }
  [[noreturn]] void unknown() const;

 private:
  std::span<const std::string_view> args_;
  std::size_t index_ = 0;
  bool only_positionals_ = false;
  std::string_view option_;
  std::optional<std::string_view> inline_value_;
  std::vector<std::string_view> positionals_;
};

/// One algorithm name: what --algorithm accepts. Names without a value are known but not built.
struct AlgorithmName {
  std::string_view name;
  std::optional<Algorithm> algorithm;
  std::string_view summary;
};
std::span<const AlgorithmName> algorithm_names();
/// The algorithm for a name; UsageError for an unknown or not yet available one.
Algorithm parse_algorithm(std::string_view name);

int run_triangulate(std::span<const std::string_view> args);
int run_stats(std::span<const std::string_view> args);
int run_generate(std::span<const std::string_view> args);

}  // namespace pear::cli
