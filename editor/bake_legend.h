// What the inspector's bake views share: visibility with the invalid points masked (NaN, drawn
// grey), the colour map and its bar, and the title in the view's top-left corner.
#pragma once

#include <vtkSmartPointer.h>

#include <array>
#include <string>

class vtkDataArray;
class vtkFloatArray;
class vtkLookupTable;
class vtkRenderer;

namespace lg {

inline constexpr const char* shown_visibility_name = "shown_visibility";

struct MaskedVisibility {
  vtkSmartPointer<vtkFloatArray> shown;  // visibility, NaN where valid is 0
  std::array<double, 2> range{0, 0};     // over the valid points
  long long invalid_points = 0;
};
MaskedVisibility mask_visibility(vtkDataArray* visibility, vtkDataArray* valid);

// Viridis over `range`, NaN grey.
vtkSmartPointer<vtkLookupTable> visibility_colours(std::array<double, 2> range);
// The colour bar of k_A at the right, with a grey "`masked`" swatch below it.
void add_visibility_bar(vtkRenderer* renderer, vtkLookupTable* lut, const char* masked);
void add_title(vtkRenderer* renderer, const std::string& text);

}  // namespace lg
