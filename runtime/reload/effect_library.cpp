// EffectLibrary: loads effects, runs reload transactions on a worker thread when the
// watcher reports edits, and swaps results in at poll(). The worker never touches a live
// version; poll() (render thread) is the only place versions change hands.
#include "fx/reload/effect_library.h"

#include <poll.h>

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <map>
#include <mutex>
#include <thread>

#include "fx/compile/spirv_cache.h"
#include "fx/model/effect_model.h"
#include "fx/model/parameter_store.h"
#include "fx/reload/include_graph.h"
#include "fx/reload/reload_transaction.h"
#include "fx/select/technique_validation.h"
#include "fx/worker_pool.h"

namespace fx {

namespace detail {
// Render-thread state of one loaded effect, shared by its handles.
struct EffectSlot {
  uint32_t id = 0;
  std::string path;  // as given to load()
  std::string key;   // absolute, normalized: the include graph's and watcher's name
  std::shared_ptr<EffectVersion> live;
  std::shared_ptr<const TechniqueChoice> techniques;  // live->techniques
  std::vector<Diagnostic> diagnostics;
  std::shared_ptr<const SourceManager> diagnostic_sources;
  bool has_criteria = false;
  StoredCriteria criteria;
  uint32_t technique = kNoIndex;
  uint32_t last = kNoIndex;  // selection memory (hysteresis)
  uint64_t plan_key = 0;
  std::optional<DeviceCaps> emulate;                // caps selection emulates, if any
  std::shared_ptr<const TechniqueChoice> emulated;  // `techniques` restricted to them

  // Re-validates the live version against the emulated caps (after a reload or a change).
  void emulate_caps() {
    emulated.reset();
    if (!emulate || !live || !techniques || !live->model) return;
    std::vector<std::vector<std::string>> extra;
    for (const TechniqueValidation& v :
         validate_techniques(*live->model, *emulate, {.programs = live->programs.get()})) {
      std::vector<std::string>& reasons = extra.emplace_back();
      for (const Diagnostic& d : v.reasons)
        reasons.push_back(emulate->name + ": " + (live->sources ? located_reason(d, *live->sources) : d.message));
      if (!v.valid && reasons.empty()) reasons.push_back(emulate->name + ": not valid");
    }
    emulated = techniques->restricted(extra);
  }
  void reselect() {
    if (!has_criteria) return;
    const auto& choice = emulated ? emulated : techniques;
    technique = choice ? choice->select(criteria.get(), last, plan_key) : kNoIndex;
  }
};
}  // namespace detail

const char* to_string(ReloadEventKind kind) {
  switch (kind) {
    case ReloadEventKind::reloaded: return "reloaded";
    case ReloadEventKind::failed: return "failed";
    case ReloadEventKind::deleted: return "deleted";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

std::string normalize(const std::string& path) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(path, ec);
  if (ec) p = path;
  return p.lexically_normal().string();
}

// A worker outcome waiting for poll().
struct Completed {
  uint32_t effect = 0;
  ReloadEventKind kind = ReloadEventKind::reloaded;
  ReloadTransactionResult tx;
  std::vector<std::string> changed;
  Clock::time_point detected;
  double detect_ms = 0;
};

// Worker-side record of a loaded effect.
struct WatchedEffect {
  std::string key;
  uint64_t serial = 0;  // of the last good version
};

struct Retiring {
  uint64_t frame;  // the poll frame at which it was replaced
  std::shared_ptr<EffectVersion> version;
};

}  // namespace

struct EffectLibrary::Impl {
  EffectLibraryOptions options;
  FrontEndOptions front_end;
  SpirvCache cache;
  std::string workers_error;                // written by start_workers()
  std::unique_ptr<CompileWorkers> workers;  // before `compiler`, which points at it
  ShaderCompiler compiler;
  std::unique_ptr<WorkerPool> own_pool;  // when the options give no executor
  TaskExecutor* executor = nullptr;      // compiles stages and effects in parallel
  std::mutex backend_mutex;              // prepare() calls one at a time

  // Render thread only.
  std::map<std::string, std::shared_ptr<detail::EffectSlot>> by_key;
  std::map<uint32_t, std::shared_ptr<detail::EffectSlot>> slots;
  std::deque<Retiring> retiring;
  uint64_t frame = 0, poll_calls = 0;
  uint32_t next_id = 1;
  EffectLibraryStats counters;

  // Shared with the worker, under `mutex`.
  std::mutex mutex;
  std::condition_variable ready;
  IncludeGraph graph;
  std::map<uint32_t, WatchedEffect> effects;
  std::deque<Completed> completed;
  bool reload_all_requested = false;
  uint64_t transactions = 0;

  // The watcher: the worker polls it; load() and the worker watch/unwatch under this lock.
  std::mutex watcher_mutex;
  std::unique_ptr<FileWatcher> watcher;
  std::thread worker;
  std::atomic<bool> stop{false};

  explicit Impl(EffectLibraryOptions o)
      : options(std::move(o)),
        cache(options.spirv_cache_dir),
        workers(start_workers()),
        compiler({}, &cache, workers.get()) {
    front_end.preprocessor.include_dirs = options.include_dirs;
    for (const std::string& d : options.defines) front_end.preprocessor.defines.push_back(parse_define(d));
    front_end.check.profile = options.profile;
    executor = options.executor;
    if (!executor) {
      own_pool = std::make_unique<WorkerPool>(options.compile_threads);
      executor = own_pool.get();
    }
    if (options.watch) {
      watcher = std::make_unique<FileWatcher>(
          FileWatcherOptions{.backend = options.watch_backend, .coalesce_window = options.coalesce});
      worker = std::thread([this] { worker_main(); });
    }
  }

  ~Impl() { stop_worker(); }

  std::unique_ptr<CompileWorkers> start_workers() {
    if (!options.compile_workers) return nullptr;
    return CompileWorkers::start(*options.compile_workers, workers_error);
  }

  void stop_worker() {
    if (!worker.joinable()) return;
    stop = true;
    watcher->interrupt();
    worker.join();
  }

  // Caller holds `mutex`. Watches / unwatches what a graph change asks for.
  void apply(const IncludeGraph::Change& change) {
    if (!watcher) return;
    std::lock_guard lock(watcher_mutex);
    for (const std::string& f : change.added) watcher->watch(f);
    for (const std::string& f : change.removed) watcher->unwatch(f);
  }
  void unwatch(const std::vector<std::string>& files) { apply({.added = {}, .removed = files}); }

  std::vector<std::string> normalized_files(const std::string& key, const std::vector<std::string>& files) {
    std::vector<std::string> out{key};
    for (const std::string& f : files) out.push_back(normalize(f));
    return out;
  }

  ReloadTransactionResult transact(const std::string& path, uint64_t serial) {
    return run_reload_transaction({.path = path,
                                   .front_end = &front_end,
                                   .compiler = &compiler,
                                   .executor = executor,
                                   .backend_mutex = &backend_mutex,
                                   .caps = options.caps ? &*options.caps : nullptr,
                                   .backend = options.backend,
                                   .serial = serial});
  }

  void worker_main() {
    while (!stop) {
      std::vector<FileEvent> events;
      int fd = watcher->wait_handle();
      if (fd >= 0) {
        int timeout_ms = 200;  // bounds the wait even if a deadline was armed elsewhere
        {
          std::lock_guard lock(watcher_mutex);
          if (auto deadline = watcher->next_deadline()) {
            auto left = std::chrono::ceil<std::chrono::milliseconds>(*deadline - Clock::now()).count();
            timeout_ms = static_cast<int>(std::clamp<long long>(left, 0, timeout_ms));
          }
        }
        pollfd pfd{fd, POLLIN, 0};
        ::poll(&pfd, 1, timeout_ms);
        if (stop) break;
        std::lock_guard lock(watcher_mutex);
        events = watcher->poll(std::chrono::milliseconds(0));
      } else {
        std::lock_guard lock(watcher_mutex);
        events = watcher->poll(std::chrono::milliseconds(20));
      }
      bool all = false;
      {
        std::lock_guard lock(mutex);
        std::swap(all, reload_all_requested);
      }
      if (!events.empty() || all) process(events, all);
    }
  }

  // Runs the transactions a batch of file events asks for (any thread; takes the locks).
  void process(const std::vector<FileEvent>& events, bool all) {
    struct Work {
      std::vector<std::string> changed, deleted;
      Clock::time_point detected = Clock::time_point::max();
      std::string key;
      uint64_t serial = 0;
    };
    Clock::time_point delivered = Clock::now();
    std::map<uint32_t, Work> work;
    {
      std::lock_guard lock(mutex);
      for (const FileEvent& e : events) {
        std::string file = e.path.string();
        for (uint32_t id : graph.effects_of(file)) {
          Work& w = work[id];
          (e.kind == FileEventKind::deleted ? w.deleted : w.changed).push_back(file);
          w.detected = std::min(w.detected, e.detected_at);
        }
      }
      if (all)
        for (const auto& [id, effect] : effects) work[id].detected = std::min(work[id].detected, delivered);
      for (auto& [id, w] : work) {
        auto it = effects.find(id);
        if (it == effects.end()) continue;
        w.key = it->second.key;
        w.serial = it->second.serial;
      }
    }
    for (auto& [id, w] : work) {
      if (w.key.empty()) continue;
      Completed done;
      done.effect = id;
      done.detected = w.detected;
      done.detect_ms = std::max(0.0, ms_between(w.detected, delivered));
      if (!w.deleted.empty()) {
        // Keep the last good version; a re-created file arrives later as a change.
        done.kind = ReloadEventKind::deleted;
        done.changed = w.deleted;
        done.changed.insert(done.changed.end(), w.changed.begin(), w.changed.end());
      } else {
        done.changed = w.changed;
        done.tx = transact(w.key, w.serial + 1);
        done.kind = done.tx.ok() ? ReloadEventKind::reloaded : ReloadEventKind::failed;
      }
      {
        std::lock_guard lock(mutex);
        auto it = effects.find(id);
        if (it == effects.end()) continue;  // unloaded meanwhile
        if (done.kind != ReloadEventKind::deleted) {
          ++transactions;
          std::vector<std::string> files = normalized_files(w.key, done.tx.files);
          // A failed attempt may have read new includes (watch them so their fix is seen)
          // but the live version still depends on the old ones: only add.
          apply(done.tx.ok() ? graph.set_files(id, files) : graph.add_files(id, files));
          if (done.tx.ok()) it->second.serial = w.serial + 1;
        }
        completed.push_back(std::move(done));
      }
      ready.notify_all();
    }
  }

  void release(uint64_t completed_frame, bool everything) {
    while (!retiring.empty() && (everything || retiring.front().frame <= completed_frame)) retiring.pop_front();
  }

  // The event for one worker outcome, applied to its slot.
  ReloadEvent swap_in(Completed& done, detail::EffectSlot& slot) {
    ReloadEvent ev;
    ev.kind = done.kind;
    ev.file = slot.path;
    ev.changed = std::move(done.changed);
    ev.ms = done.tx.ms;
    ev.ms.detect = done.detect_ms;
    ev.recompiled = std::move(done.tx.recompiled);
    ev.sources = done.tx.sources;
    if (done.kind == ReloadEventKind::deleted) {
      ++counters.deletions;
      for (const std::string& f : ev.changed) {
        DiagnosticSink sink;
        sink.warning("reload-file-deleted", {}, f + " was deleted; keeping the last good version of " + slot.path);
        ev.diagnostics.push_back(sink.diagnostics().front());
      }
    } else if (done.kind == ReloadEventKind::failed) {
      ++counters.failures;
      ev.diagnostics = done.tx.diagnostics;
      slot.diagnostics = done.tx.diagnostics;
      slot.diagnostic_sources = done.tx.sources;
    } else {
      ++counters.reloads;
      std::shared_ptr<EffectVersion> next(done.tx.version.release());
      ev.diagnostics = done.tx.diagnostics;
      if (slot.live) {
        if (slot.live->params && next->params) ev.defaults_changed = remap(*slot.live->params, *next->params);
        if (slot.live->model && next->model)
          report_removed_parameters(*slot.live->model, *next->model, slot.path, ev.diagnostics);
        retiring.push_back({frame, std::move(slot.live)});
      }
      slot.live = std::move(next);
      slot.techniques = slot.live->techniques;
      slot.emulate_caps();
      slot.reselect();
      slot.diagnostics = ev.diagnostics;
      slot.diagnostic_sources = done.tx.sources;
    }
    ev.serial = slot.live ? slot.live->serial : 0;
    if (slot.techniques && slot.technique != kNoIndex) ev.technique = slot.techniques->name(slot.technique);
    ev.ms.total = std::max(0.0, ms_between(done.detected, Clock::now()));
    return ev;
  }

  // A warning per parameter of `old_model` that `new_model` lacks (by name and type): its
  // handles are inert from now on.
  static void report_removed_parameters(const EffectModel& old_model, const EffectModel& new_model,
                                        const std::string& path, std::vector<Diagnostic>& out) {
    DiagnosticSink sink;
    for (const Parameter& p : old_model.parameters) {
      uint32_t i = new_model.find_parameter(p.name);
      if (i == kNoIndex) {
        sink.warning("reload-parameter-removed", {},
                     "parameter '" + p.name + "' was removed from " + path + "; its handles are now inert");
      } else if (new_model.parameters[i].type.to_string() != p.type.to_string()) {
        sink.warning("reload-parameter-retyped", {},
                     "parameter '" + p.name + "' changed type from " + p.type.to_string() + " to " +
                         new_model.parameters[i].type.to_string() + " in " + path +
                         "; its old handles are now inert and its value is the new default");
      }
    }
    out.insert(out.end(), sink.diagnostics().begin(), sink.diagnostics().end());
  }
};

EffectLibrary::EffectLibrary(EffectLibraryOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}

EffectLibrary::~EffectLibrary() {
  // Stop the worker first: nothing may be building while versions are released.
  impl_->stop_worker();
  for (auto& [id, slot] : impl_->slots) {
    slot->live.reset();
    slot->techniques.reset();
    slot->technique = kNoIndex;
  }
  impl_->release(0, true);
}

EffectHandle EffectLibrary::load(const std::string& path) { return load(std::vector<std::string>{path}).front(); }

std::vector<EffectHandle> EffectLibrary::load(const std::vector<std::string>& paths) {
  Impl& d = *impl_;
  std::vector<std::shared_ptr<detail::EffectSlot>> fresh;  // not loaded before this call
  for (const std::string& path : paths) {
    std::string key = normalize(path);
    auto known = [&](const std::shared_ptr<detail::EffectSlot>& s) { return s->key == key; };
    if (d.by_key.count(key) || std::any_of(fresh.begin(), fresh.end(), known)) continue;
    auto slot = std::make_shared<detail::EffectSlot>();
    slot->id = d.next_id++;
    slot->path = path;
    slot->key = key;
    // Watch before reading, so an edit racing with this load is still reported.
    std::lock_guard lock(d.mutex);
    d.effects[slot->id] = {key, 0};
    d.apply(d.graph.set_files(slot->id, {key}));
    fresh.push_back(std::move(slot));
  }
  std::vector<ReloadTransactionResult> results(fresh.size());
  d.executor->for_each(fresh.size(), [&](size_t i) { results[i] = d.transact(fresh[i]->key, 1); });
  for (size_t i = 0; i < fresh.size(); ++i) {
    detail::EffectSlot& slot = *fresh[i];
    ReloadTransactionResult& tx = results[i];
    {
      std::lock_guard lock(d.mutex);
      std::vector<std::string> files = d.normalized_files(slot.key, tx.files);
      d.apply(d.graph.set_files(slot.id, files));
      if (tx.ok()) d.effects[slot.id].serial = 1;
    }
    slot.diagnostics = tx.diagnostics;
    slot.diagnostic_sources = tx.sources;
    if (tx.ok()) {
      slot.live = std::shared_ptr<EffectVersion>(tx.version.release());
      slot.techniques = slot.live->techniques;
      slot.emulate_caps();
    }
    d.by_key[slot.key] = fresh[i];
    d.slots[slot.id] = fresh[i];
  }
  std::vector<EffectHandle> handles;
  for (const std::string& path : paths) handles.push_back(EffectHandle(d.by_key.at(normalize(path))));
  return handles;
}

void EffectLibrary::unload(const EffectHandle& effect) {
  Impl& d = *impl_;
  if (!effect.slot_) return;
  auto it = d.slots.find(effect.slot_->id);
  if (it == d.slots.end() || it->second != effect.slot_) return;
  detail::EffectSlot& slot = *it->second;
  {
    std::lock_guard lock(d.mutex);
    d.unwatch(d.graph.remove(slot.id));
    d.effects.erase(slot.id);
    std::erase_if(d.completed, [&](const Completed& c) { return c.effect == slot.id; });
  }
  if (slot.live) d.retiring.push_back({d.frame, std::move(slot.live)});
  slot.live.reset();
  slot.techniques.reset();
  slot.technique = kNoIndex;
  d.by_key.erase(slot.key);
  d.slots.erase(it);
}

std::vector<ReloadEvent> EffectLibrary::poll(uint64_t frame) {
  Impl& d = *impl_;
  d.frame = frame;
  if (frame >= d.options.frames_in_flight) d.release(frame - d.options.frames_in_flight, false);
  std::deque<Completed> done;
  {
    std::lock_guard lock(d.mutex);
    done.swap(d.completed);
  }
  std::vector<ReloadEvent> events;
  for (Completed& c : done) {
    auto it = d.slots.find(c.effect);
    if (it == d.slots.end()) continue;
    events.push_back(d.swap_in(c, *it->second));
  }
  done.clear();  // failed attempts' versions were never built; nothing else to keep
  if (d.options.on_event)
    for (const ReloadEvent& ev : events) d.options.on_event(ev);
  return events;
}

std::vector<ReloadEvent> EffectLibrary::poll() { return poll(impl_->poll_calls++); }

void EffectLibrary::release_completed(uint64_t completed_frame) { impl_->release(completed_frame, false); }
void EffectLibrary::release_all() { impl_->release(0, true); }

bool EffectLibrary::wait(std::chrono::milliseconds timeout) {
  std::unique_lock lock(impl_->mutex);
  return impl_->ready.wait_for(lock, timeout, [&] { return !impl_->completed.empty(); });
}

void EffectLibrary::reload_all() {
  Impl& d = *impl_;
  if (!d.worker.joinable()) {
    d.process({}, true);
    return;
  }
  {
    std::lock_guard lock(d.mutex);
    d.reload_all_requested = true;
  }
  d.watcher->interrupt();
}

CompileWorkers* EffectLibrary::compile_workers() const { return impl_->workers.get(); }

const std::string& EffectLibrary::compile_workers_error() const { return impl_->workers_error; }

EffectLibraryStats EffectLibrary::stats() const {
  const Impl& d = *impl_;
  EffectLibraryStats s = d.counters;
  s.retiring = d.retiring.size();
  std::lock_guard lock(impl_->mutex);
  s.transactions = d.transactions;
  s.watched_files = d.graph.file_count();
  return s;
}

std::vector<Diagnostic> EffectLibrary::watcher_diagnostics() const {
  if (!impl_->watcher) return {};
  std::lock_guard lock(impl_->watcher_mutex);
  return impl_->watcher->diagnostics().diagnostics();
}

const EffectLibraryOptions& EffectLibrary::options() const { return impl_->options; }

// EffectHandle ------------------------------------------------------------------------

bool EffectHandle::ok() const { return slot_ && slot_->live; }
const std::string& EffectHandle::path() const {
  static const std::string kEmpty;
  return slot_ ? slot_->path : kEmpty;
}
std::shared_ptr<const EffectVersion> EffectHandle::version() const { return slot_ ? slot_->live : nullptr; }
uint64_t EffectHandle::serial() const { return ok() ? slot_->live->serial : 0; }
const std::vector<Diagnostic>& EffectHandle::diagnostics() const {
  static const std::vector<Diagnostic> kNone;
  return slot_ ? slot_->diagnostics : kNone;
}
std::shared_ptr<const SourceManager> EffectHandle::diagnostic_sources() const {
  return slot_ ? slot_->diagnostic_sources : nullptr;
}

Param EffectHandle::param(std::string_view name_or_semantic) const {
  ParameterStore* s = params();
  if (!s) return {};
  Param p = s->find(name_or_semantic);
  return p.valid() ? p : s->by_semantic(name_or_semantic);
}

ParameterStore* EffectHandle::params() const { return ok() ? slot_->live->params.get() : nullptr; }

uint32_t EffectHandle::select(const SelectionCriteria& criteria) const {
  if (!slot_) return kNoIndex;
  slot_->criteria = StoredCriteria(criteria);
  slot_->has_criteria = true;
  slot_->reselect();
  return slot_->technique;
}

uint32_t EffectHandle::select() const {
  if (!slot_) return kNoIndex;
  slot_->criteria = StoredCriteria();
  slot_->has_criteria = true;
  slot_->reselect();
  return slot_->technique;
}

uint32_t EffectHandle::select(const SelectionCriteria& criteria, const DeviceCaps* emulate) const {
  if (!slot_) return kNoIndex;
  slot_->emulate = emulate ? std::optional<DeviceCaps>(*emulate) : std::nullopt;
  slot_->emulate_caps();
  return select(criteria);
}

std::shared_ptr<const TechniqueChoice> EffectHandle::choice() const {
  if (!slot_) return nullptr;
  return slot_->emulated ? slot_->emulated : slot_->techniques;
}

uint32_t EffectHandle::technique() const { return slot_ ? slot_->technique : kNoIndex; }
std::string EffectHandle::technique_name() const {
  if (!slot_ || !slot_->techniques || slot_->technique == kNoIndex) return {};
  return std::string(slot_->techniques->name(slot_->technique));
}

}  // namespace fx
