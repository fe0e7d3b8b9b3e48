// What an EffectLibrary reports about a reload: one event per effect per burst of edits.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/source_manager.h"

namespace fx {

// reloaded: the new version is live; failed: the last good version stays live and
// `diagnostics` say why; deleted: a file of the effect is gone, the effect stays as it was.
enum class ReloadEventKind : uint8_t { reloaded, failed, deleted };

// "reloaded", "failed" or "deleted".
const char* to_string(ReloadEventKind kind);

// Where the time of one reload went, in milliseconds.
struct ReloadTimings {
  double detect = 0;       // first edit record -> watcher delivery (coalescing included)
  double parse = 0;        // preprocess, parse, check, effect model, selection plan
  double compile = 0;      // translation units and programs (SPIR-V cache hits included)
  double glslang = 0;      // of `compile`, time spent inside glslang
  double pipeline = 0;     // the backend's GPU objects (pipelines, layouts, samplers)
  double first_frame = 0;  // the backend's warm-up draw (driver shader compile at first use)
  double total = 0;        // first edit record -> swapped in by poll() (or reported)
};

// One reload outcome, delivered by EffectLibrary::poll() and its callback.
struct ReloadEvent {
  ReloadEventKind kind = ReloadEventKind::reloaded;
  std::string file;                     // the effect file, as given to load()
  std::vector<std::string> changed;     // the files whose edits caused this (effect or includes)
  std::vector<std::string> recompiled;  // "technique.pass.stage" units glslang compiled afresh
  // reloaded: parameters the application never set (or reset) whose value is now the
  // edited file's different default (remap's result).
  std::vector<std::string> defaults_changed;
  ReloadTimings ms;
  // Errors (failed), warnings (reloaded: removed parameters, technique changes, ...).
  std::vector<Diagnostic> diagnostics;
  // The sources the diagnostics point into (render with fx::render_text / render_json).
  std::shared_ptr<const SourceManager> sources;
  uint64_t serial = 0;    // the live version's serial after this event
  std::string technique;  // the technique re-selected with the last criteria
};

}  // namespace fx
