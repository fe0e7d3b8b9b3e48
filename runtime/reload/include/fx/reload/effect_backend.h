// The seam between reload transactions and a GPU binding: the binding prepares the GPU
// objects of a new effect version off the render thread, so poll() only swaps pointers.
#pragma once
#include <memory>

#include "fx/diagnostic.h"

namespace fx {

struct EffectVersion;

// GPU objects of one effect version (pipelines, descriptor set layouts, samplers). The
// library destroys it with its version, on the thread that calls poll(), only after the
// frames in flight that could use it have retired.
class BackendEffect {
 public:
  virtual ~BackendEffect() = default;
};

// Time the backend spent, reported in the reload event.
struct BackendTimings {
  double pipeline_ms = 0;     // creating pipelines and layouts
  double first_frame_ms = 0;  // a warm-up draw (drivers like lavapipe compile at first use)
};

// Implemented by a Vulkan effect binding. prepare() runs on the reload worker thread (and
// on the caller's thread for EffectLibrary::load), concurrently with the application's
// rendering: it must only create objects, never touch the live version's.
class EffectBackend {
 public:
  virtual ~EffectBackend() = default;
  // GPU objects for `version`; nullptr (with errors in `diags`) rejects the version, and
  // the last good one stays live.
  virtual std::shared_ptr<BackendEffect> prepare(const EffectVersion& version, DiagnosticSink& diags,
                                                 BackendTimings& timings) = 0;
};

}  // namespace fx
