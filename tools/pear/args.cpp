#include <charconv>
#include <limits>
#include <string>

#include "cli.hpp"

namespace pear::cli {

std::optional<std::string_view> Args::next_option() {
  while (index_ < args_.size()) {
    const std::string_view arg = args_[index_++];
    if (only_positionals_ || arg == "-" || !arg.starts_with('-')) {
      positionals_.push_back(arg);
      continue;
    }
    if (arg == "--") {
      only_positionals_ = true;
      continue;
    }
    inline_value_.reset();
    option_ = arg;
    if (const auto eq = arg.find('='); arg.starts_with("--") && eq != std::string_view::npos) {
      option_ = arg.substr(0, eq);
      inline_value_ = arg.substr(eq + 1);
    }
    return option_;
  }
  return std::nullopt;
}

std::string_view Args::value() {
  if (inline_value_) return *inline_value_;
  if (index_ >= args_.size()) throw UsageError("option " + std::string(option_) + " needs a value");
  return args_[index_++];
}

std::uint64_t Args::integer(std::uint64_t min, std::uint64_t max) {
  const std::string_view text = value();
  std::uint64_t number = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (ec != std::errc() || ptr != text.data() + text.size() || number < min || number > max)
    throw UsageError("option " + std::string(option_) + " expects an integer from " +
                     std::to_string(min) + " to " + std::to_string(max) + ", not '" +
                     std::string(text) + "'");
  return number;
}

std::size_t Args::byte_size() {
  const std::string_view text = value();
  std::size_t number = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
  const std::string_view unit(ptr, static_cast<std::size_t>(text.data() + text.size() - ptr));
  const int shift = unit.empty() ? 0 : unit == "K" ? 10 : unit == "M" ? 20 : unit == "G" ? 30 : -1;
  if (ec != std::errc() || shift < 0 || number == 0 ||
      number > (std::numeric_limits<std::size_t>::max() >> shift))
    throw UsageError("option " + std::string(option_) +
                     " expects a size in bytes above 0, optionally with K, M or G (1024-based), "
                     "not '" +
                     std::string(text) + "'");
  return number << shift;
}

void Args::no_value() {
  if (inline_value_) throw UsageError("option " + std::string(option_) + " takes no value");
}

void Args::unknown() const {
  throw UsageError("unknown option " + std::string(option_));
}

namespace {
// The one table of algorithm names.
constexpr AlgorithmName names[] = {
    {"auto", Algorithm::automatic,
     "small: sequential; 2 parts: divide-and-conquer; more: partition-and-cut;\n"
     "                          large coastline-like, 1 to 4 parts: divide-and-conquer"},
    {"sequential", Algorithm::sequential, "FIST-style ear clipping on one thread"},
    {"partition-and-cut", Algorithm::partition_and_cut,
     "parallel: chains between landmarks, each clipped by its own task"},
    {"mark-and-cut", Algorithm::mark_and_cut,
     "parallel: rounds of clipping every second ear at once"},
    {"divide-and-conquer", Algorithm::divide_and_conquer,
     "parallel: vertical split lines, parts clipped in parallel, Steiner points removed"},
};
}  // namespace

std::span<const AlgorithmName> algorithm_names() {
  return names;
}

Algorithm parse_algorithm(std::string_view name) {
  for (const AlgorithmName& entry : names) {
    if (entry.name != name) continue;
    if (!entry.algorithm)
      throw UsageError("algorithm " + std::string(name) + " is not available in this build");
    return *entry.algorithm;
  }
  std::string known;
  for (const AlgorithmName& entry : names)
    known += (known.empty() ? "" : ", ") + std::string(entry.name);
  throw UsageError("unknown algorithm '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace pear::cli
