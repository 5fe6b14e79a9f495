#include "runtime/scene/light_alpha.h"

namespace lg {

float light_alpha_cutoff(const PbrMaterial& m) {
  switch (m.alpha_mode) {
    case AlphaMode::mask:
      return m.alpha_cutoff;
    case AlphaMode::blend:
      return 0.5f;
    case AlphaMode::opaque:
      break;
  }
  return -1.0f;
}

}  // namespace lg
