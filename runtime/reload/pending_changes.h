// Coalesces bursts of file activity: a file is ready once quiet for the window.
#pragma once
#include <chrono>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace fx::detail {

// What the watcher saw happen to a watched name.
enum class Activity {
  written,    // closed after writing, or renamed onto the name: new content is complete
  created,    // created; the writer has probably not closed it yet
  removed,    // deleted or renamed away
  rescanned,  // a snapshot comparison found it different
};

class PendingChanges {
 public:
  using Clock = std::chrono::steady_clock;

  struct Ready {
    std::string key;
    bool written = false;  // a completed write was seen (report even if content matches)
    Clock::time_point first_seen;
  };

  PendingChanges(Clock::duration window, Clock::duration close_grace) : window_(window), close_grace_(close_grace) {}

  void note(const std::string& key, Activity activity, Clock::time_point now);
  void forget(const std::string& key) { pending_.erase(key); }
  bool empty() const { return pending_.empty(); }

  // Removes and returns the files quiet for their window at `now`.
  std::vector<Ready> take_ready(Clock::time_point now);
  // The earliest time a pending file becomes ready.
  std::optional<Clock::time_point> next_deadline() const;

 private:
  struct Entry {
    Clock::time_point first_seen, last_activity;
    bool written = false;
    bool awaiting_close = false;
  };
  Clock::time_point ready_at(const Entry& e) const {
    return e.last_activity + (e.awaiting_close ? close_grace_ : window_);
  }

  Clock::duration window_, close_grace_;
  std::unordered_map<std::string, Entry> pending_;
};

}  // namespace fx::detail
