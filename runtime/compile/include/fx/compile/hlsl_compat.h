// Compatibility with pre-release (2001-2002) HLSL, as in the seeds' wood shader: vec3,
// len, frc, sample1d/sample3d, volumetexture. A prelude maps what has a modern meaning;
// a scan reports what it cannot map or maps only approximately.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace fx {

// HLSL text to put before pre-release code (it has no #line: put `#line 1 "file.fx"` after it).
std::string_view pre_release_hlsl_prelude();

// A pre-release construct the prelude does not map exactly.
struct CompatIssue {
  std::string name;    // the construct, e.g. "sample1d"
  size_t offset = 0;   // first use in the scanned source
  std::string reason;  // what fxkit does instead, or why it cannot
};

// Scans `source` (comments skipped) for constructs the prelude maps approximately or not at all.
std::vector<CompatIssue> pre_release_hlsl_issues(std::string_view source);

}  // namespace fx
