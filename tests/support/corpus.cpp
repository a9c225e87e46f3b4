#include "corpus.hpp"

#if PEAR_CORPUS_WITH_ZLIB
#include <zlib.h>
#endif

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace pear::corpus {
namespace {

fs::path from_environment(const char* variable, const char* fallback) {
  const char* value = std::getenv(variable);
  return value != nullptr && *value != '\0' ? value : fallback;
}

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, '\t');) fields.push_back(field);
  return fields;
}

std::size_t count(const std::string& text, const fs::path& manifest, std::size_t line) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size())
    throw std::runtime_error(manifest.string() + ":" + std::to_string(line) + ": \"" + text +
                             "\" is not a count");
  return value;
}

/// The MANIFEST's columns by their header names; npos for a column it lacks.
struct Columns {
  std::size_t file, vertices, holes, source, licence;

  explicit Columns(const std::vector<std::string>& header) {
    const auto find = [&](std::string_view name) {
      const auto it = std::find(header.begin(), header.end(), name);
      return it == header.end() ? std::string::npos : std::size_t(it - header.begin());
    };
    file = find("file");
    vertices = find("vertices");
    holes = find("holes");
    source = find("source");
    licence = find("license/attribution");
  }
};

File read_row(const std::string& line, const Columns& columns, const Folder& folder,
              std::size_t number) {
  const fs::path manifest = folder.dir / "MANIFEST.tsv";
  const std::vector<std::string> fields = split_tabs(line);
  const auto field = [&](std::size_t column) -> std::string {
    if (column == std::string::npos) return {};
    if (column >= fields.size())
      throw std::runtime_error(manifest.string() + ":" + std::to_string(number) + ": " +
                               std::to_string(fields.size()) + " fields, fewer than the header's");
    return fields[column];
  };
  File file;
  file.folder = folder.name;
  file.file = field(columns.file);
  file.path = folder.dir / file.file;
  if (columns.vertices != std::string::npos)
    file.vertices = count(field(columns.vertices), manifest, number);
  if (columns.holes != std::string::npos)
    file.holes = count(field(columns.holes), manifest, number);
  file.source = field(columns.source);
  file.licence = field(columns.licence);
  for (const char* defect : {"GEOS:", "NOT SIMPLE", "DEGENERATE"})
    file.valid = file.valid && line.find(defect) == std::string::npos;
  if (!readable(file.path)) file.missing = "built without zlib: cannot read " + file.path.string();
  return file;
}

}  // namespace

fs::path shared_root() {
  return from_environment("PEAR_SHARED_CORPUS", PEAR_DEFAULT_SHARED_CORPUS);
}

fs::path bundled_root() {
  return from_environment("PEAR_CORPUS", PEAR_DEFAULT_CORPUS);
}

Folder read_folder(const fs::path& root, std::string_view name) {
  Folder folder;
  folder.name = name;
  folder.dir = root / name;
  if (!fs::is_directory(folder.dir)) {
    folder.missing = "no folder " + folder.dir.string();
    return folder;
  }
  std::ifstream in(folder.dir / "MANIFEST.tsv");
  if (!in) {
    folder.missing = "no MANIFEST.tsv in " + folder.dir.string();
    return folder;
  }
  std::string line;
  std::getline(in, line);
  const Columns columns(split_tabs(line));
  if (columns.file == std::string::npos)
    throw std::runtime_error((folder.dir / "MANIFEST.tsv").string() + ": no \"file\" column");
  for (std::size_t number = 2; std::getline(in, line); ++number)
    if (!line.empty()) folder.files.push_back(read_row(line, columns, folder, number));
  return folder;
}

bool readable(const fs::path& path) {
  return PEAR_CORPUS_WITH_ZLIB || path.extension() != ".gz";
}

std::string read_text(const fs::path& path) {
  if (path.extension() != ".gz") {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path.string());
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
  }
#if PEAR_CORPUS_WITH_ZLIB
  gzFile file = gzopen(path.c_str(), "rb");
  if (file == nullptr) throw std::runtime_error("cannot open " + path.string());
  std::string text;
  char chunk[1 << 16];
  int got = 0;
  while ((got = gzread(file, chunk, sizeof chunk)) > 0)
    text.append(chunk, static_cast<std::size_t>(got));
  gzclose(file);
  if (got < 0) throw std::runtime_error("cannot decompress " + path.string());
  return text;
#else
  throw std::runtime_error("built without zlib: cannot read " + path.string());
#endif
}

}  // namespace pear::corpus
