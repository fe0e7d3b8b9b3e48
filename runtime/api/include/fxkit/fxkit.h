// fxkit's public API: #include <fxkit/fxkit.h> and link fxkit::fxkit.
//
//   Device   fxkit on a Vulkan device (the engine's, or a headless one for tools)
//   Effect   a loaded .fx file, live-reloaded; Param, Technique, Criteria, Scene
//   Mesh, Offscreen   built-in geometry and a readable image, for tools and samples
//
// samples/minimal is the whole integration in one short file; docs/embedding.md explains it.
#pragma once
#include "fxkit/device.h"
#include "fxkit/effect.h"
#include "fxkit/mesh.h"
#include "fxkit/message.h"
#include "fxkit/offscreen.h"
#include "fxkit/script_frame.h"
#include "fxkit/target.h"
