// What a FileWatcher reports: one event per file per burst of edits.
#pragma once
#include <chrono>
#include <filesystem>

namespace fx {

// Whether the file now has new content (or exists again) or is gone.
enum class FileEventKind { changed, deleted };

// "changed" or "deleted".
const char* to_string(FileEventKind kind);

// One settled change of one watched file.
struct FileEvent {
  std::filesystem::path path;  // as first passed to FileWatcher::watch()
  FileEventKind kind = FileEventKind::changed;
  // When the watcher first noticed this burst of activity (not when it was delivered);
  // delivery follows once the file has been quiet for the coalescing window.
  std::chrono::steady_clock::time_point detected_at;
};

}  // namespace fx
