#include "pending_changes.h"

#include <algorithm>

namespace fx::detail {

void PendingChanges::note(const std::string& key, Activity activity, Clock::time_point now) {
  auto [it, inserted] = pending_.try_emplace(key);
  Entry& e = it->second;
  if (inserted) e.first_seen = now;
  e.last_activity = now;
  switch (activity) {
    case Activity::written:
      e.written = true;
      e.awaiting_close = false;
      break;
    case Activity::created: e.awaiting_close = true; break;
    case Activity::removed: e.awaiting_close = false; break;
    case Activity::rescanned: break;
  }
}

std::vector<PendingChanges::Ready> PendingChanges::take_ready(Clock::time_point now) {
  std::vector<Ready> ready;
  for (auto it = pending_.begin(); it != pending_.end();) {
    if (ready_at(it->second) <= now) {
      ready.push_back({it->first, it->second.written, it->second.first_seen});
      it = pending_.erase(it);
    } else {
      ++it;
    }
  }
  // Hash-map order is arbitrary; report in the order the edits happened.
  std::sort(ready.begin(), ready.end(), [](const Ready& a, const Ready& b) {
    return a.first_seen != b.first_seen ? a.first_seen < b.first_seen : a.key < b.key;
  });
  return ready;
}

std::optional<PendingChanges::Clock::time_point> PendingChanges::next_deadline() const {
  std::optional<Clock::time_point> earliest;
  for (const auto& [key, e] : pending_) {
    auto at = ready_at(e);
    if (!earliest || at < *earliest) earliest = at;
  }
  return earliest;
}

}  // namespace fx::detail
