// IncludeGraph: two maps kept in step (effect -> files, file -> effects).
#include "fx/reload/include_graph.h"

namespace fx {

void IncludeGraph::link(EffectId effect, const std::string& file, Change& change) {
  if (!files_[effect].insert(file).second) return;
  std::set<EffectId>& readers = readers_[file];
  if (readers.empty()) change.added.push_back(file);
  readers.insert(effect);
}

void IncludeGraph::unlink(EffectId effect, const std::string& file, std::vector<std::string>& removed) {
  auto it = readers_.find(file);
  if (it == readers_.end()) return;
  it->second.erase(effect);
  if (it->second.empty()) {
    readers_.erase(it);
    removed.push_back(file);
  }
}

IncludeGraph::Change IncludeGraph::set_files(EffectId effect, const std::vector<std::string>& files) {
  Change change;
  std::set<std::string> wanted(files.begin(), files.end());
  std::set<std::string>& current = files_[effect];
  for (auto it = current.begin(); it != current.end();) {
    if (wanted.count(*it)) {
      ++it;
      continue;
    }
    unlink(effect, *it, change.removed);
    it = current.erase(it);
  }
  for (const std::string& f : files) link(effect, f, change);
  return change;
}

IncludeGraph::Change IncludeGraph::add_files(EffectId effect, const std::vector<std::string>& files) {
  Change change;
  for (const std::string& f : files) link(effect, f, change);
  return change;
}

std::vector<std::string> IncludeGraph::remove(EffectId effect) {
  std::vector<std::string> removed;
  auto it = files_.find(effect);
  if (it == files_.end()) return removed;
  for (const std::string& f : it->second) unlink(effect, f, removed);
  files_.erase(it);
  return removed;
}

std::vector<IncludeGraph::EffectId> IncludeGraph::effects_of(const std::string& file) const {
  auto it = readers_.find(file);
  if (it == readers_.end()) return {};
  return {it->second.begin(), it->second.end()};
}

std::vector<std::string> IncludeGraph::files_of(EffectId effect) const {
  auto it = files_.find(effect);
  if (it == files_.end()) return {};
  return {it->second.begin(), it->second.end()};
}

}  // namespace fx
