// What the kernel says about this process's memory, for the huge-page tests: the VmFlags
// line of the mapping holding an address ("hg": advised for transparent huge pages).
#pragma once
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

namespace fx::testing {

// The VmFlags of the mapping of this process that holds `address`, or "" if none was found.
inline std::string vm_flags_at(const void* address) {
  std::ifstream smaps("/proc/self/smaps");
  const auto a = reinterpret_cast<uintptr_t>(address);
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = a >= begin && a < end;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line;
    }
  }
  return "";
}

inline bool kernel_has_transparent_huge_pages() {
  std::ifstream f("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string s;
  std::getline(f, s);
  return !s.empty() && s.find("[never]") == std::string::npos;
}

}  // namespace fx::testing
