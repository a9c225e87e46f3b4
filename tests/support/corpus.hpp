// The real-polygon corpora, for tests, fuzz targets and benchmarks alike: ../shared/corpus (large,
// and absent on some machines) and the bundled corpus/. Each folder's MANIFEST.tsv, read by its
// header line, lists the files with their vertex and hole counts, source and licence; a folder
// that cannot be read says why instead of looking empty. No GoogleTest and no pear here.
#pragma once

#include <cstddef>
#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace pear::corpus {

namespace fs = std::filesystem;

/// The shared corpus: PEAR_SHARED_CORPUS, else ../shared/corpus beside the source tree.
fs::path shared_root();
/// The bundled corpus: PEAR_CORPUS, else the source tree's corpus/.
fs::path bundled_root();

/// One row of a folder's MANIFEST.tsv.
struct File {
  std::string folder;  ///< "earcut", "coast", ...
  std::string file;    ///< the name in its folder: "rain.json", "eurasia_gshhg_full.json.gz"
  fs::path path;
  std::size_t vertices = 0;  ///< without the closing duplicates (0 when the MANIFEST has none)
  std::size_t holes = 0;
  std::string source;
  std::string licence;
  /// The row records no defect: no GEOS verdict, NOT SIMPLE or DEGENERATE anywhere in it.
  bool valid = true;
  /// Why the file cannot be read (the folder is absent, .gz without zlib); empty when it can.
  std::string missing;

  std::string name() const { return folder + "/" + file; }
};

inline void PrintTo(const File& file, std::ostream* out) {
  *out << file.name();
}

/// A folder's files in MANIFEST order; `missing` says why there are none.
struct Folder {
  std::string name;
  fs::path dir;
  std::vector<File> files;
  /// Why the folder cannot be read ("no folder ...", "no MANIFEST.tsv in ..."); empty when read.
  std::string missing;
};

/// Reads root/name/MANIFEST.tsv. Throws std::runtime_error on a malformed MANIFEST.
Folder read_folder(const fs::path& root, std::string_view name);

/// Whether read_text can read the file: false for .gz in a build without zlib.
bool readable(const fs::path& path);

/// The file's contents, .gz decompressed. Throws std::runtime_error, naming the file, when it
/// cannot be opened or decompressed.
std::string read_text(const fs::path& path);

}  // namespace pear::corpus
