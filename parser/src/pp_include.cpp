// #include path handling: normalization, search order, the case-insensitive fallback for
// effects written on Windows, and the default disk hooks.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "fx/ascii_case.h"
#include "fx/diagnostic.h"
#include "pp_internal.h"

namespace fx {

FileLoader disk_file_loader() {
  return [](const std::string& path) -> std::optional<std::string> {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return std::move(text).str();
  };
}

DirectoryLister disk_directory_lister() {
  return [](const std::string& folder) {
    std::vector<std::string> names;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(folder.empty() ? "." : folder, ec), end; !ec && it != end;
         it.increment(ec))
      names.push_back(it->path().filename().string());
    return names;
  };
}

std::pair<std::string, std::string> parse_define(std::string_view arg) {
  size_t eq = arg.find('=');
  if (eq == std::string_view::npos) return {std::string(arg), "1"};
  return {std::string(arg.substr(0, eq)), std::string(arg.substr(eq + 1))};
}

namespace pp {
namespace {

bool is_absolute(std::string_view p) {
  return (!p.empty() && p[0] == '/') || (p.size() > 1 && p[1] == ':');  // "/x", "C:/x"
}

std::vector<std::string_view> split(std::string_view p) {
  std::vector<std::string_view> parts;
  size_t begin = 0;
  while (begin <= p.size()) {
    size_t end = p.find('/', begin);
    if (end == std::string_view::npos) end = p.size();
    if (end > begin) parts.push_back(p.substr(begin, end - begin));
    begin = end + 1;
  }
  return parts;
}

}  // namespace

std::string normalize_path(std::string_view path) {
  std::string p(path);
  for (char& c : p)
    if (c == '\\') c = '/';
  bool root = !p.empty() && p[0] == '/';
  std::vector<std::string_view> out;
  for (std::string_view part : split(p)) {
    if (part == ".") continue;
    if (part == ".." && !out.empty() && out.back() != "..") {
      out.pop_back();
      continue;
    }
    if (part == ".." && root) continue;  // "/.." is "/"
    out.push_back(part);
  }
  std::string result = root ? "/" : "";
  for (size_t i = 0; i < out.size(); ++i) {
    if (i) result.push_back('/');
    result.append(out[i]);
  }
  return result;
}

std::string parent_folder(std::string_view path) {
  std::string p = normalize_path(path);
  size_t slash = p.rfind('/');
  if (slash == std::string::npos) return "";
  if (slash == 0) return "/";
  return p.substr(0, slash);
}

std::string join_path(std::string_view folder, std::string_view name) {
  std::string n = normalize_path(name);
  if (folder.empty() || is_absolute(n)) return n;
  return normalize_path(std::string(folder) + "/" + n);
}

bool names_a_folder(std::string_view name) {
  return !name.empty() && name[0] != '.' && name.find_first_of("/\\") != std::string_view::npos &&
         !is_absolute(normalize_path(name));
}

std::vector<std::string> ancestor_folders(std::string_view folder, size_t levels) {
  std::vector<std::string> out;
  std::string f = normalize_path(folder);
  while (out.size() < levels && f != "/" && !(f.size() == 2 && f[1] == ':')) {
    const size_t slash = f.rfind('/');
    const std::string_view last =
        slash == std::string::npos ? std::string_view(f) : std::string_view(f).substr(slash + 1);
    if (f.empty() || last == "..") f = f.empty() ? std::string("..") : f + "/..";
    else f = parent_folder(f);
    out.push_back(f);
  }
  return out;
}

std::optional<ResolvedInclude> resolve_include(std::string_view name, const std::vector<std::string>& folders,
                                               const FileLoader& loader, const DirectoryLister& lister) {
  std::vector<std::string> candidates;
  if (is_absolute(normalize_path(name))) candidates.push_back(normalize_path(name));
  else
    for (const std::string& folder : folders) candidates.push_back(join_path(folder, name));
  for (const std::string& c : candidates)
    if (std::optional<std::string> text = loader(c)) return ResolvedInclude{c, std::move(*text)};
  if (!lister) return std::nullopt;
  for (const std::string& c : candidates) {
    // Walk the path one component at a time, taking the exact name when it exists and a
    // case-insensitive match otherwise.
    std::string real = c[0] == '/' ? "/" : "";
    bool found = true;
    for (std::string_view part : split(c)) {
      std::string next;
      if (part == "..") {
        next = std::string(part);
      } else {
        std::vector<std::string> entries = lister(real);
        const std::string* match = nullptr;
        for (const std::string& e : entries)
          if (e == part) match = &e;
        if (!match)
          for (const std::string& e : entries)
            if (iequals(e, part)) {
              match = &e;
              break;
            }
        if (!match) {
          found = false;
          break;
        }
        next = *match;
      }
      real = real.empty() ? next : real == "/" ? "/" + next : real + "/" + next;
    }
    if (!found) continue;
    if (std::optional<std::string> text = loader(real)) return ResolvedInclude{real, std::move(*text), true};
  }
  return std::nullopt;
}

MissingInclude describe_missing_include(std::string_view name, const std::vector<std::string>& folders,
                                        const DirectoryLister& lister) {
  MissingInclude out;
  const std::string wanted = normalize_path(name);
  const std::string subfolder = parent_folder(wanted);
  const size_t slash = wanted.rfind('/');
  const std::string file = slash == std::string::npos ? wanted : wanted.substr(slash + 1);
  std::vector<std::string> names;
  for (const std::string& folder : folders) {
    const std::string shown = folder.empty() ? "." : folder;
    if (std::find(out.searched.begin(), out.searched.end(), shown) == out.searched.end()) out.searched.push_back(shown);
    if (!lister || is_absolute(wanted)) continue;
    for (std::string& entry : lister(join_path(folder, subfolder))) names.push_back(std::move(entry));
  }
  if (lister && is_absolute(wanted)) names = lister(parent_folder(wanted));
  const std::string guess = closest_match(file, std::vector<std::string_view>(names.begin(), names.end()));
  if (!guess.empty() && guess != file) out.near = subfolder.empty() ? guess : subfolder + "/" + guess;
  return out;
}

}  // namespace pp
}  // namespace fx
