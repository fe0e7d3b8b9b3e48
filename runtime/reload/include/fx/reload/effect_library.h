// The application-facing facade: load effects, set parameters through handles that
// survive reloads, select techniques, and call poll() once per frame to swap in the
// versions a background worker rebuilt after the files (or their includes) were edited.
// Usage (load, param, set, select, draw, poll per frame): docs/hot-reload.md.
//
// Threading: load(), poll(), unload() and every EffectHandle call belong to one thread
// (the render thread). The library runs one worker thread for watching and rebuilding.
#pragma once
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fx/checker.h"
#include "fx/compile/compile_workers.h"
#include "fx/diagnostic.h"
#include "fx/reload/effect_backend.h"
#include "fx/reload/file_watcher.h"
#include "fx/reload/reload_event.h"
#include "fx/reload/technique_choice.h"
#include "fx/select/device_caps.h"

namespace fxkit {
struct Param;  // fx/model/param.h
}

namespace fx {

using fxkit::Param;

// Declared, not included, so this header stays light: include fx/model/parameter_store.h
// (Param, ParameterStore) and fx/select/selection.h (SelectionCriteria) where you use them.
class ParameterStore;
struct SelectionCriteria;
struct EffectVersion;
class TaskExecutor;

struct EffectLibraryOptions {
  std::vector<std::string> include_dirs;  // searched after the including file's folder
  std::vector<std::string> defines;       // "NAME" or "NAME=VALUE", as -D
  EffectProfile profile = EffectProfile::automatic;
  bool watch = true;                       // reload on edits (a worker thread is started)
  std::chrono::milliseconds coalesce{50};  // quiet time before an edited file is reloaded
  WatchBackend watch_backend = WatchBackend::automatic;
  EffectBackend* backend = nullptr;  // not owned; nullptr: no GPU objects
  std::optional<DeviceCaps> caps;    // techniques are validated against these
  std::string spirv_cache_dir;       // "" keeps the SPIR-V cache in memory only
  // Threads that compile shaders (the stages of an effect, the effects of one load() call):
  // 0: one per hardware thread; 1: the calling thread alone. Ignored when `executor` is set.
  uint32_t compile_threads = 0;
  TaskExecutor* executor = nullptr;  // not owned: the application's own job system
  // Set: glslang runs in worker processes (fx/compile/compile_workers.h), so a compiler
  // crash on an edited file fails that load or reload instead of the application. When the
  // workers cannot start, shaders compile in this process and compile_workers_error() says
  // why. Unset: in this process.
  std::optional<CompileWorkerOptions> compile_workers;
  uint32_t frames_in_flight = 2;                     // how long replaced versions are kept (poll frames)
  std::function<void(const ReloadEvent&)> on_event;  // called from poll(), before it returns
};

// Counters for tests and tools.
struct EffectLibraryStats {
  uint64_t transactions = 0;  // reload attempts run by the worker
  uint64_t reloads = 0;       // versions swapped in by poll()
  uint64_t failures = 0;      // failed reload attempts reported
  uint64_t deletions = 0;     // deleted events reported
  size_t retiring = 0;        // replaced versions waiting for their frames to retire
  size_t watched_files = 0;   // files in the include graph
};

namespace detail {
struct EffectSlot;
}

// A loaded effect. Copies refer to the same effect; the handle stays valid across reloads.
// After unload() or the library's destruction it is inert (ok() false, version() null).
class EffectHandle {
 public:
  EffectHandle() = default;

  // Whether this handle refers to an effect at all.
  bool valid() const { return slot_ != nullptr; }
  // Whether a good version is live (false when the first load failed and no fix came yet).
  bool ok() const;
  // The effect file as given to load().
  const std::string& path() const;
  // The live version (nullptr when !ok()). Holding it keeps it alive past its retirement.
  std::shared_ptr<const EffectVersion> version() const;
  // Serial of the live version (0 when none): changes on every successful reload.
  uint64_t serial() const;
  // Diagnostics of the last load or reload attempt, and the sources they point into.
  const std::vector<Diagnostic>& diagnostics() const;
  std::shared_ptr<const SourceManager> diagnostic_sources() const;

  // A parameter by exact name, else by semantic (case-insensitive); invalid if neither
  // (or when no version is live).
  Param param(std::string_view name_or_semantic) const;
  // The live parameter values (nullptr when !ok()): set/get through it. Handles from
  // earlier versions stay valid (translated); removed parameters' handles are inert.
  // Values set through it survive reloads; the others take the edited file's defaults
  // (ReloadEvent::defaults_changed, docs/parameters.md).
  ParameterStore* params() const;

  // Chooses a technique (index into version()->model.techniques, or kNoIndex) and
  // remembers the criteria: every reload re-selects with them.
  uint32_t select(const SelectionCriteria& criteria) const;
  // Selects with default criteria (every scheme, no distance), remembered likewise.
  uint32_t select() const;
  // Selects as a device with `emulate` would (a D3D caps profile: the historic generations),
  // among the techniques this device can draw; remembered with the criteria and applied to
  // every reload. nullptr selects for this device again.
  uint32_t select(const SelectionCriteria& criteria, const DeviceCaps* emulate) const;
  // The techniques as selection sees them: validated on this device, and against the
  // emulated caps when select() was given some. Null before the first good version.
  std::shared_ptr<const TechniqueChoice> choice() const;
  // The last selected technique (re-selected after reloads); kNoIndex before select().
  uint32_t technique() const;
  std::string technique_name() const;

 private:
  friend class EffectLibrary;
  explicit EffectHandle(std::shared_ptr<detail::EffectSlot> slot) : slot_(std::move(slot)) {}
  std::shared_ptr<detail::EffectSlot> slot_;
};

class EffectLibrary {
 public:
  explicit EffectLibrary(EffectLibraryOptions options = {});
  // Stops the worker and releases every version (the device must be idle by then).
  ~EffectLibrary();
  EffectLibrary(const EffectLibrary&) = delete;
  EffectLibrary& operator=(const EffectLibrary&) = delete;

  // Loads (synchronously) and starts watching the file and its includes. Loading the same
  // path twice returns the same effect. A failed load still returns a handle (ok() false,
  // diagnostics() say why) that becomes ok once an edit fixes the file.
  EffectHandle load(const std::string& path);
  // Loads several effects, compiling them in parallel on the compile threads (or the
  // executor); the handles are in the order of `paths`. With a backend, its prepare() calls
  // are made one at a time.
  std::vector<EffectHandle> load(const std::vector<std::string>& paths);
  // Stops watching the effect; its version is retired like a replaced one and the
  // handle (and its copies) become inert.
  void unload(const EffectHandle& effect);

  // At a frame boundary: swaps in completed reloads, retires replaced versions and
  // returns (and passes to on_event) what happened. `frame` is the number of the frame
  // about to be recorded: a version replaced now is destroyed at the first poll() whose
  // frame is >= now + frames_in_flight.
  std::vector<ReloadEvent> poll(uint64_t frame);
  // The same, counting calls as frames.
  std::vector<ReloadEvent> poll();
  // Destroys replaced versions whose last frame is <= `completed_frame` (for applications
  // that know from a fence or timeline semaphore which frames finished).
  void release_completed(uint64_t completed_frame);
  // Destroys every replaced version now (after vkDeviceWaitIdle).
  void release_all();

  // Blocks until the worker has a result for poll() or `timeout` passes; true if one is
  // ready. For tools and tests that have no frame loop.
  bool wait(std::chrono::milliseconds timeout);

  // Rebuilds every loaded effect now (the worker reports the outcome through poll()).
  void reload_all();

  EffectLibraryStats stats() const;
  // The compile worker pool (null: shaders compile in this process), and why it is null
  // although the options asked for one ("" otherwise).
  CompileWorkers* compile_workers() const;
  const std::string& compile_workers_error() const;
  // Problems of the watcher itself (inotify unavailable, watch limits).
  std::vector<Diagnostic> watcher_diagnostics() const;
  const EffectLibraryOptions& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fx
