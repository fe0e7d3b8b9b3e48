// One effect checked as `fxkit check` checks it: the front end (and semantic model) and,
// unless syntax-only, every shader compiled (each pass stage of each technique and every
// element of the shader arrays passes index). The result is rendered and self-contained, so results made on
// several threads, or read back from the cache, print alike.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fx/frontend.h"

namespace fx {
class EffectPrograms;
class EffectUnits;
struct EffectModel;
class ShownOnce;
class TaskExecutor;
class ShaderCompiler;
struct DeviceCaps;
}  // namespace fx

namespace fx::tools {

class CheckCache;

struct EffectCheckSettings {
  fx::FrontEndOptions front_end;
  bool compile = true;  // false: --syntax-only (the front end's checks alone)
  bool werror = false;
  const fx::ShaderCompiler* compiler = nullptr;  // required when compile (runtime builds)
  fx::TaskExecutor* executor = nullptr;          // the stages in parallel; nullptr: in turn
  const fx::DeviceCaps* caps = nullptr;          // --caps: validate every technique on these
  bool caps_compile = true;                      // false: --no-compile for --caps
};

struct EffectCheck {
  std::string file;                // as named on the command line or found in a folder
  std::vector<std::string> files;  // files read: the effect first, then its includes
  size_t errors = 0, warnings = 0;
  bool runnable = true;                                  // with caps: some technique is valid there
  std::string text;                                      // the diagnostics as text (for stderr)
  std::string caps_text;                                 // with caps: the technique lines (for stdout)
  nlohmann::json diagnostics = nlohmann::json::array();  // fx::render_json of them
  nlohmann::json effect;                                 // the effect's summary for --format json
  double ms = 0;                                         // wall time of the check (of the first run, if cached)
  bool from_cache = false;

  bool failed() const { return errors > 0 || !runnable; }
  bool clean() const { return !failed() && warnings == 0; }
};

EffectCheck check_effect(const std::string& file, const EffectCheckSettings& settings);

// Runtime builds: what compiling every shader of an effect's units reports (through its
// programs), added to `shown` after what `diags` holds, each diagnostic once with "also
// reported for" notes. check_effect runs it on its EffectFile; the language server on the
// units of its document snapshot, and publishes the same. With `model`, the compute units of
// its texture shaders too (docs/effect-model.md "Texture shaders").
void check_shaders(const fx::EffectUnits& units, fx::EffectPrograms& programs, const EffectCheckSettings& settings,
                   fx::DiagnosticSink& diags, fx::ShownOnce& shown, const fx::EffectModel* model = nullptr);

// Every file checked into results[i] on settings.executor (files and, within them, stages
// in parallel; in turn without one), each looked up in and stored to `cache` when given
// (runtime builds). `finished(i)` is called from the thread that completed file i.
void check_effects(const std::vector<std::string>& files, const EffectCheckSettings& settings, CheckCache* cache,
                   std::vector<EffectCheck>& results, const std::function<void(size_t)>& finished = {});

// The cache's form of a result, and back (false for a record of another shape).
nlohmann::json to_json(const EffectCheck& check);
bool from_json(const nlohmann::json& j, EffectCheck& check);

}  // namespace fx::tools
