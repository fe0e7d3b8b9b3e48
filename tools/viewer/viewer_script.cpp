// ViewerScript: parses --script files and runs their commands between frames.
#include "viewer_script.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace {

// "1,0.5,2" -> {1, 0.5, 2}; false on anything that is not a number.
bool parse_values(const std::string& text, std::vector<float>& out) {
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');) {
    char* end = nullptr;
    const float v = std::strtof(item.c_str(), &end);
    if (item.empty() || *end != '\0') return false;
    out.push_back(v);
  }
  return !out.empty();
}

}  // namespace

std::optional<ViewerScript> ViewerScript::load(const std::string& path, std::string& error) {
  std::ifstream in(path);
  if (!in) return error = "cannot read script " + path, std::nullopt;
  ViewerScript script;
  script.path_ = path;
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    line = line.substr(0, line.find('#'));
    std::stringstream words(line);
    std::string verb, arg, extra;
    if (!(words >> verb)) continue;
    words >> arg >> extra;
    ScriptCommand c;
    c.line = line_no;
    auto bad = [&](const std::string& why) {
      error = path + ":" + std::to_string(line_no) + ": error: " + why;
      return std::nullopt;
    };
    char* end = nullptr;
    if (verb == "frames") {
      c.kind = ScriptCommand::Kind::frames;
      c.number = std::strtod(arg.c_str(), &end);
      if (arg.empty() || *end != '\0' || c.number < 1) return bad("frames wants a count >= 1");
    } else if (verb == "set") {
      c.kind = ScriptCommand::Kind::set;
      c.arg = arg;
      if (arg.empty() || !parse_values(extra, c.values)) return bad("set wants NAME V[,V...]");
      extra.clear();
    } else if (verb == "technique") {
      c.kind = ScriptCommand::Kind::technique;
      c.arg = arg;
      if (arg.empty()) return bad("technique wants a name or auto");
    } else if (verb == "texture") {
      c.kind = ScriptCommand::Kind::texture;
      c.arg = arg;
      c.file = extra;
      if (arg.empty() || extra.empty()) return bad("texture wants NAME FILE");
      extra.clear();
    } else if (verb == "wait-reload") {
      c.kind = ScriptCommand::Kind::wait_reload;
      c.number = arg.empty() ? 10.0 : std::strtod(arg.c_str(), &end);
      if (!arg.empty() && (*end != '\0' || c.number <= 0)) return bad("wait-reload wants seconds > 0");
    } else if (verb == "screenshot" || verb == "screenshot-window") {
      c.kind = verb == "screenshot" ? ScriptCommand::Kind::screenshot : ScriptCommand::Kind::screenshot_window;
      c.arg = arg;
      if (arg.empty()) return bad("screenshot wants a file name");
    } else if (verb == "quit") {
      c.kind = ScriptCommand::Kind::quit;
    } else {
      return bad("unknown command '" + verb +
                 "' (frames, set, technique, texture, wait-reload, screenshot, screenshot-window, quit)");
    }
    if (!extra.empty()) return bad("unexpected '" + extra + "' after " + verb);
    script.commands_.push_back(std::move(c));
  }
  return script;
}

std::string ViewerScript::fail(const ScriptCommand& c, const std::string& message) const {
  return path_ + ":" + std::to_string(c.line) + ": error: " + message;
}

ScriptFrame ViewerScript::before_frame(fxkit::Effect& effect, TechniquePanel& panel, fxkit::Technique& technique,
                                       bool reloaded) {
  ScriptFrame frame;
  if (frames_left_ > 0 && --frames_left_ > 0) return frame;
  if (waiting_) {
    if (!reloaded && std::chrono::steady_clock::now() < deadline_) return frame;
    if (!reloaded) {
      frame.error =
          fail(commands_[next_ - 1], "no reload within " + std::to_string(int(commands_[next_ - 1].number)) + " s");
      frame.quit = true;
      return frame;
    }
    waiting_ = false;
  }
  while (next_ < commands_.size()) {
    const ScriptCommand& c = commands_[next_++];
    switch (c.kind) {
      case ScriptCommand::Kind::frames: frames_left_ = int(c.number); return frame;
      case ScriptCommand::Kind::wait_reload:
        waiting_ = true;
        deadline_ = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                           std::chrono::duration<double>(c.number));
        return frame;
      case ScriptCommand::Kind::screenshot:
      case ScriptCommand::Kind::screenshot_window:
        frame.screenshot = c.arg;
        frame.with_ui = c.kind == ScriptCommand::Kind::screenshot_window;
        frames_left_ = 1;
        return frame;
      case ScriptCommand::Kind::technique:
        panel.pin(effect, technique, c.arg);
        if (c.arg != "auto" && !technique.valid()) {
          frame.error = fail(c, "technique '" + c.arg + "': " + technique.reason());
          frame.quit = true;
          return frame;
        }
        break;
      case ScriptCommand::Kind::set: {
        const fxkit::Param p = effect.param(c.arg);
        if (!effect.set(p, std::span<const float>(c.values))) {
          frame.error = fail(c, "cannot set '" + c.arg + "' to " + std::to_string(c.values.size()) +
                                    " value(s): no such float parameter, or another size");
          frame.quit = true;
          return frame;
        }
        break;
      }
      case ScriptCommand::Kind::texture:
        if (!effect.set_texture_file(c.arg, c.file)) {
          const std::vector<fxkit::Message> messages = effect.messages();
          frame.error = fail(c, "cannot sample '" + c.file + "' for '" + c.arg + "'" +
                                    (messages.empty() ? std::string() : ": " + messages.back().text));
          frame.quit = true;
          return frame;
        }
        break;
      case ScriptCommand::Kind::quit: frame.quit = true; return frame;
    }
  }
  frame.quit = true;  // the end of the script
  return frame;
}
