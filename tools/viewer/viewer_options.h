// The command line of fxkit-view.
#pragma once
#include <string>

struct ViewerOptions {
  std::string file;
  std::string mesh = "sphere";  // sphere, torus, teapot, quad or an .obj file
  std::string technique;        // "" : selection
  std::string save_params, load_params, screenshot;
  std::string script;  // --script F (viewer_script.h)
  int frames = 0;      // 0: until the window closes
  int width = 1280, height = 800;
  bool validate = false;
};

// false with `error` (the usage) when the arguments are not understood.
bool parse_viewer_options(int argc, char** argv, ViewerOptions& options, std::string& error);

extern const char* const kViewerUsage;
