// numeric_components: the HLSL scalar and vector type names.
#include "numeric_type.h"

namespace fx::detail {

uint32_t numeric_components(std::string_view type) {
  for (std::string_view base : {"float", "half", "int", "uint", "bool", "double", "dword", "min16float", "min16int"}) {
    if (type == base) return 1;
    if (type.size() == base.size() + 1 && type.starts_with(base) && type.back() >= '1' && type.back() <= '4')
      return static_cast<uint32_t>(type.back() - '0');
  }
  return 0;
}

}  // namespace fx::detail
