// Which loaded effects read which files, so an edit reloads exactly the effects that
// include the edited file (directly or through other includes).
#pragma once
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace fx {

// Files are compared as given: callers pass normalized absolute paths.
class IncludeGraph {
 public:
  using EffectId = uint32_t;

  // What set_files changed: files nobody read before / nobody reads any more (the
  // caller watches / unwatches them).
  struct Change {
    std::vector<std::string> added, removed;
  };

  // Replaces the files `effect` reads (its own file first, then every include).
  Change set_files(EffectId effect, const std::vector<std::string>& files);
  // Adds files to `effect`'s set without dropping any (a failed reload may have read new
  // includes, but the last good version still depends on the old ones).
  Change add_files(EffectId effect, const std::vector<std::string>& files);
  // Forgets `effect`; returns the files nobody reads any more.
  std::vector<std::string> remove(EffectId effect);

  // The effects that read `file`, in id order.
  std::vector<EffectId> effects_of(const std::string& file) const;
  // The files `effect` reads, sorted.
  std::vector<std::string> files_of(EffectId effect) const;
  // Number of distinct files read by any effect.
  size_t file_count() const { return readers_.size(); }

 private:
  void link(EffectId effect, const std::string& file, Change& change);
  void unlink(EffectId effect, const std::string& file, std::vector<std::string>& removed);

  std::map<EffectId, std::set<std::string>> files_;
  std::map<std::string, std::set<EffectId>> readers_;
};

}  // namespace fx
