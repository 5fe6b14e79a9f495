// A volume bake's .vti as VTK itself reads it (vtkXMLImageDataReader, what ParaView uses): the
// grid's extent, origin and spacing and every point array, value for value.
#include <gtest/gtest.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLImageDataReader.h>

#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>

#include "nodes/occlusion/bake/bake_file.h"
#include "nodes/occlusion/bake/bake_outputs.h"
#include "nodes/raytrace/vti_file.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/occlusion/ray_test_scenes.h"

namespace lg {
namespace {

// A comment from a node id such as "a--b" (ids may hold dashes): VTK refuses an XML comment that
// holds "--", so the file must not.
TEST(VtiFile, ACommentWithDoubleDashesStillMakesAFileVtkReads) {
  VtiImage image;
  image.comment = "dumped from node a--b---c";
  image.dims = {2, 1, 1};
  const std::vector<float> values = {1.0f, 2.0f};
  image.arrays.push_back({"v", 1, values});
  const std::string text = encode_vti(image);
  EXPECT_EQ(text.find("--", text.find("<!--") + 4), text.find("-->")) << text.substr(0, 200);
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("lumagraph-vti-comment-" + std::to_string(::getpid()) + ".vti");
  std::ofstream(path, std::ios::binary) << text;
  auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  std::filesystem::remove(path);
  int dims[3] = {0, 0, 0};
  reader->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 2);
}

TEST(VolumeBakeFile, VtkReadsTheGridAndEveryArray) {
  const WorldMesh mesh = make_world_mesh(test::scene_of(
      {test::floor_quad(3.0f), {make_box(glm::vec3(1.0f)), glm::translate(glm::mat4(1.0f), {0.0f, 0.5f, 0.0f})}}));
  const BakeDomain domain = BakeDomain::volume(mesh, {7, 5, 6});
  const RayScene scene(mesh.positions, mesh.indices);
  BakeFile file;
  file.header = make_bake_header(domain, mesh, "box", {.rays = 32}, 1, 0, 1);
  file.data = run_bake(scene, domain, {.rays = 32}, 1, file.header.range);

  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("lumagraph-vti-test-" + std::to_string(::getpid()) + ".vti");
  std::ofstream(path, std::ios::binary) << encode_vti(file);
  auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  std::filesystem::remove(path);
  vtkImageData* image = reader->GetOutput();
  ASSERT_NE(image, nullptr);
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 7);
  EXPECT_EQ(dims[1], 5);
  EXPECT_EQ(dims[2], 6);
  double origin[3], spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  for (int a = 0; a < 3; ++a) {
    EXPECT_DOUBLE_EQ(origin[a], domain.origin()[a]);
    EXPECT_DOUBLE_EQ(spacing[a], domain.spacing()[a]);
  }
  struct Expected {
    const char* name;
    int components;
    const std::vector<float>* values;
  };
  for (const Expected& e :
       {Expected{"visibility", 1, &file.data.visibility}, Expected{"bent_normal", 3, &file.data.bent_normal},
        Expected{"valid", 1, &file.data.valid}}) {
    auto* array = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray(e.name));
    ASSERT_NE(array, nullptr) << e.name;
    ASSERT_EQ(array->GetNumberOfComponents(), e.components) << e.name;
    ASSERT_EQ(size_t(array->GetNumberOfValues()), e.values->size()) << e.name;
    for (size_t i = 0; i < e.values->size(); ++i)
      ASSERT_EQ(array->GetValue(vtkIdType(i)), (*e.values)[i]) << e.name << " " << i;
  }
  EXPECT_STREQ(image->GetPointData()->GetScalars()->GetName(), "visibility");
  size_t inside = 0;
  for (float v : file.data.valid) inside += v == 0.0f;
  EXPECT_GT(inside, 0u);  // the box holds grid points: the validity channel is exercised
}

}  // namespace
}  // namespace lg
