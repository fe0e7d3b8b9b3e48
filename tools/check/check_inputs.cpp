#include "check_inputs.h"

#include <fnmatch.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

namespace fx::tools {
namespace {

namespace fs = std::filesystem;

bool glob_matches(const std::vector<std::string>& globs, const fs::path& relative) {
  for (const std::string& g : globs) {
    const bool by_path = g.find('/') != std::string::npos;
    const std::string subject = by_path ? relative.generic_string() : relative.filename().string();
    if (::fnmatch(g.c_str(), subject.c_str(), 0) == 0) return true;
  }
  return false;
}

// The files `file` names in #include directives that exist, by canonical path. A textual
// scan: directives inside #if branches count too, so a file included under some define is
// still left to its includer.
std::vector<std::string> scanned_includes(const fs::path& file, const std::vector<std::string>& include_dirs) {
  static const std::regex directive(R"(^[ \t]*#[ \t]*include[ \t]*["<]([^">\r]+)[">])");
  std::ifstream in(file, std::ios::binary);
  std::vector<std::string> out;
  std::string line;
  std::smatch m;
  while (std::getline(in, line)) {
    if (line.find("include") == std::string::npos || !std::regex_search(line, m, directive)) continue;
    std::string name = m[1].str();
    std::replace(name.begin(), name.end(), '\\', '/');
    std::vector<fs::path> candidates{file.parent_path() / name};
    for (const std::string& dir : include_dirs) candidates.push_back(fs::path(dir) / name);
    for (const fs::path& c : candidates) {
      std::error_code ec;
      if (fs::is_regular_file(c, ec)) {
        out.push_back(fs::weakly_canonical(c, ec).string());
        break;
      }
    }
  }
  return out;
}

}  // namespace

bool parse_shard(const std::string& text, unsigned& shard, unsigned& shards) {
  size_t slash = text.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == text.size()) return false;
  try {
    size_t used = 0;
    unsigned long k = std::stoul(text.substr(0, slash), &used);
    if (used != slash) return false;
    unsigned long n = std::stoul(text.substr(slash + 1), &used);
    if (used != text.size() - slash - 1 || k < 1 || k > n || n > 100000) return false;
    shard = static_cast<unsigned>(k);
    shards = static_cast<unsigned>(n);
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

unsigned shard_of(const std::string& file, unsigned shards) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a: the same on every machine and build
  for (char c : fs::path(file).lexically_normal().generic_string()) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return static_cast<unsigned>(h % shards) + 1;
}

bool find_check_inputs(const std::vector<std::string>& paths, const CheckInputOptions& options, CheckInputs& out,
                       std::string& error) {
  std::set<std::string> named;     // files named on the command line
  std::vector<std::string> found;  // files found in folders
  for (const std::string& p : paths) {
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) {
      named.insert(p);
      continue;
    }
    if (!fs::is_directory(p, ec)) {
      error = "cannot read '" + p + "'";
      return false;
    }
    fs::recursive_directory_iterator it(p, fs::directory_options::skip_permission_denied, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
      if (!it->is_regular_file(ec)) continue;
      fs::path relative = it->path().lexically_relative(p);
      if (glob_matches(options.include_globs, relative) && !glob_matches(options.exclude_globs, relative))
        found.push_back(it->path().string());
    }
    if (ec) {
      error = "cannot read folder '" + p + "': " + ec.message();
      return false;
    }
  }
  // A file another found file includes is checked as part of its includer.
  std::set<std::string> included;
  for (const std::string& f : found)
    for (std::string& inc : scanned_includes(f, options.include_dirs)) included.insert(std::move(inc));
  std::set<std::string> roots(named);
  for (const std::string& f : found) {
    std::error_code ec;
    if (!named.count(f) && included.count(fs::weakly_canonical(f, ec).string())) ++out.included_only;
    else roots.insert(f);
  }
  for (const std::string& f : roots) {
    if (options.shards > 1 && shard_of(f, options.shards) != options.shard) ++out.other_shards;
    else out.files.push_back(f);
  }
  return true;
}

}  // namespace fx::tools
