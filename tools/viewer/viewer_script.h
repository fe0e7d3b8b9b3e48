// fxkit-view --script F: a few commands run between frames, so the viewer is driven end to
// end by tests and scripts. One command per line; `#` starts a comment:
//   frames N              draw N frames before the next command
//   set NAME V[,V...]     set a numeric parameter (all its components)
//   technique NAME|auto   pin a technique, or return to selection
//   texture NAME F.png    sample an image file for a texture parameter
//   wait-reload [SECONDS] draw until a reload (good or failed) is reported; 10 s by default
//   screenshot F.png      write the scene of the next frame drawn (without the UI)
//   screenshot-window F.png  the same with the UI: the whole window
//   quit                  end the run (the end of the file does too)
// A command that cannot run (an unknown parameter, a reload that never comes) ends the run
// with `F:LINE: error: ...` and exit status 1.
#pragma once
#include <fxkit/fxkit.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "technique_panel.h"

struct ScriptCommand {
  enum class Kind { frames, set, technique, texture, wait_reload, screenshot, screenshot_window, quit };
  Kind kind = Kind::quit;
  std::string arg;            // parameter, technique or file name
  std::string file;           // texture
  std::vector<float> values;  // set
  double number = 0;          // frames (count), wait-reload (seconds)
  int line = 0;
};

// What the frame about to be drawn must do.
struct ScriptFrame {
  bool quit = false;
  std::string screenshot;  // write this frame's scene here
  bool with_ui = false;    // the whole window, UI included
  std::string error;       // quit with this error (`F:LINE: error: ...`)
};

class ViewerScript {
 public:
  // The commands of `path`; nullopt with `error` (`F:LINE: error: ...`) when one is malformed.
  static std::optional<ViewerScript> load(const std::string& path, std::string& error);

  // Before each frame: runs the commands due now. `reloaded`: a reload was reported since the
  // last call.
  ScriptFrame before_frame(fxkit::Effect& effect, TechniquePanel& panel, fxkit::Technique& technique, bool reloaded);

 private:
  std::string fail(const ScriptCommand& c, const std::string& message) const;

  std::string path_;
  std::vector<ScriptCommand> commands_;
  size_t next_ = 0;
  int frames_left_ = 0;
  bool waiting_ = false;
  std::chrono::steady_clock::time_point deadline_{};
};
