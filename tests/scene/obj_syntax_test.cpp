// Malformed OBJ geometry is refused with its line and column (runtime/scene/obj_syntax.h):
// non-finite and malformed numbers, missing coordinates, faces with too few or too many
// corners, and indices that are zero, out of range or malformed; and the lenient forms the
// format allows (relative and forward indices, comments, CRLF, underflowing numbers) still load;
// random edits of the cube load or fail with a SceneError. MTL libraries: outside the OBJ file's
// folder they are refused, and so are the malformed numbers of the statements that make the
// material.
#include "runtime/scene/obj_syntax.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <random>

#include "import_test_support.h"
#include "runtime/scene/contained_path.h"
#include "runtime/scene/mesh_import.h"

namespace lg {
namespace {

using test::error_of;
using test::fixture;
using test::read_bytes;
using test::write_variant;

const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

// The error of importing `text` as a file, without the file's path in front.
std::string refusal(const std::string& name, const std::string& text) {
  std::string path = write_variant(name, text);
  World w;
  std::string message = error_of([&] { import_obj(w, path); });
  EXPECT_EQ(message.rfind(path, 0), 0u) << message;
  return message.substr(std::min(message.size(), path.size()));
}

// The world made by importing `text`, which must load.
World imported(const std::string& name, const std::string& text) {
  World w;
  import_obj(w, write_variant(name, text));
  return w;
}

TEST(ObjSyntax, NonFiniteAndMalformedNumbersAreRefused) {
  EXPECT_EQ(refusal("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"),
            ":2:3: error: expected a finite number, got 'nan'");
  EXPECT_EQ(refusal("inf.obj", triangle + "vn 0 -inf 1\nf 1//1 2//1 3//1\n"),
            ":4:6: error: expected a finite number, got '-inf'");
  EXPECT_EQ(refusal("garbage.obj", triangle + "vt 1.0abc 0\nf 1/1 2/1 3/1\n"),
            ":4:4: error: expected a finite number, got '1.0abc'");
  // Beyond the float range: tinyobjloader would read it as infinity.
  EXPECT_EQ(refusal("huge.obj", "v 0 0 1e39\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
            ":1:7: error: expected a finite number, got '1e39'");
  EXPECT_EQ(refusal("hex.obj", "v 0x10 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
            ":1:3: error: expected a finite number, got '0x10'");
}

TEST(ObjSyntax, MissingOrExtraCoordinatesAreRefused) {
  EXPECT_EQ(refusal("short_v.obj", "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
            ":1:1: error: a vertex needs x y z, optionally followed by w or by an r g b colour; got 2 numbers");
  EXPECT_EQ(refusal("five_v.obj", "v 0 0 0 1 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
            ":1:1: error: a vertex needs x y z, optionally followed by w or by an r g b colour; got 5 numbers");
  EXPECT_EQ(refusal("short_vn.obj", triangle + "  vn 0 1\nf 1//1 2//1 3//1\n"),
            ":4:3: error: a normal needs x y z; got 2 numbers");
  EXPECT_EQ(refusal("empty_vt.obj", triangle + "vt\nf 1/1 2/1 3/1\n"),
            ":4:1: error: a texture coordinate needs u, optionally v and w; got 0 numbers");
}

TEST(ObjSyntax, BadFacesAreRefused) {
  EXPECT_EQ(refusal("two_corners.obj", triangle + "f 1 2\n"), ":4:1: error: a face needs at least 3 corners; got 2");
  EXPECT_EQ(refusal("zero.obj", triangle + "f 0 1 2\n"),
            ":4:3: error: vertex index 0 is not valid: OBJ counts from 1, or back from -1");
  EXPECT_EQ(refusal("beyond.obj", triangle + "f 1 2 9\n"),
            ":4:7: error: vertex index 9 is beyond the file's 3 vertices");
  EXPECT_EQ(refusal("no_uvs.obj", triangle + "f 1 2 3/1\n"),
            ":4:9: error: texture coordinate index 1 is beyond the file's 0 texture coordinates");
  EXPECT_EQ(refusal("before_start.obj", triangle + "f -1 -2 -4\nv 0 0 1\n"),
            ":4:9: error: vertex index -4 reaches before the first vertex: 3 vertices above this line");
  EXPECT_EQ(refusal("overflow.obj", triangle + "f 1 2 99999999999999999999\n"),
            ":4:7: error: vertex index 99999999999999999999 is out of range");
  EXPECT_EQ(refusal("past_int.obj", triangle + "f 1 2 2147483648\n"),
            ":4:7: error: vertex index 2147483648 is out of range");
  EXPECT_EQ(refusal("letters.obj", triangle + "f 1 2 3x\n"), ":4:7: error: expected an integer vertex index; got '3x'");
  EXPECT_EQ(refusal("face_comment.obj", triangle + "f 1 2 3 # the only face\n"),
            ":4:9: error: a comment may not follow a face's corners (tinyobjloader reads it as index 0); put it on a "
            "line of its own");
  for (std::string corner : {"1/2/3/4", "1//", "/1", "1/", "/", "1/1/"})
    EXPECT_EQ(refusal("corner.obj", triangle + "vt 0 0\nvn 0 0 1\nf 1 2 3 " + corner + "\n"),
              ":6:9: error: expected a face corner like 3, 3/1, 3//2 or 3/1/2; got '" + corner + "'");
}

TEST(ObjSyntax, FacesHaveAtMostTheCornerLimit) {
  // A regular polygon: tinyobjloader clips it into corners - 2 triangles.
  auto polygon = [](size_t corners) {
    std::string text, face = "f";
    for (size_t i = 0; i < corners; ++i) {
      float angle = 6.2831853f * static_cast<float>(i) / static_cast<float>(corners);
      text += "v " + std::to_string(std::cos(angle)) + " " + std::to_string(std::sin(angle)) + " 0\n";
      face += " " + std::to_string(i + 1);
    }
    return text + face + "\n";
  };
  World w = imported("polygon.obj", polygon(max_obj_face_corners));
  ASSERT_EQ(w.meshes().size(), 1u);
  EXPECT_EQ(w.meshes()[0]->indices.size(), 3 * (max_obj_face_corners - 2));
  size_t too_many = max_obj_face_corners + 1;
  EXPECT_EQ(refusal("big_polygon.obj", polygon(too_many)),
            ":" + std::to_string(too_many + 1) + ":1: error: a face may have at most " +
                std::to_string(max_obj_face_corners) + " corners; this one has " + std::to_string(too_many));
}

TEST(ObjSyntax, EveryProblemIsReportedInFileOrderUpToTheLimit) {
  // The forward reference on line 1 can only be judged at the end, yet comes first.
  EXPECT_EQ(check_obj_text("several.obj", "f 1 2 7\nv 0 0 nan\nv 1 0 0\nv 0 1\n").to_string(),
            "several.obj:1:7: error: vertex index 7 is beyond the file's 3 vertices\n"
            "several.obj:2:7: error: expected a finite number, got 'nan'\n"
            "several.obj:4:1: error: a vertex needs x y z, optionally followed by w or by an r g b colour; got 2 "
            "numbers\n");
  auto bad_lines = [](size_t n) {
    std::string text;
    for (size_t i = 0; i < n; ++i) text += "v nan 0 0\n";
    return text;
  };
  EXPECT_EQ(check_obj_text("limit.obj", bad_lines(max_obj_errors)).items().size(), max_obj_errors);
  Diagnostics capped = check_obj_text("many.obj", bad_lines(max_obj_errors + 10));
  ASSERT_EQ(capped.items().size(), max_obj_errors + 1);
  EXPECT_EQ(capped.items()[max_obj_errors - 1].pos.line, max_obj_errors);
  EXPECT_EQ(capped.items().back().to_string(),
            "many.obj: error: the check stopped after " + std::to_string(max_obj_errors) + " problems");
}

TEST(ObjSyntax, LinesEndAsTinyobjloaderEndsThemAndColumnsCountCharacters) {
  for (std::string end : {"\n", "\r\n", "\r"})
    EXPECT_EQ(check_obj_text("ends.obj", "v 0 0 0" + end + "v 0 nan 0" + end).to_string(),
              "ends.obj:2:5: error: expected a finite number, got 'nan'\n");
  // "\u00e9" is two bytes of UTF-8 and one column.
  EXPECT_EQ(check_obj_text("utf8.obj", "v \u00e9 nan 0\n").to_string(),
            "utf8.obj:1:3: error: expected a finite number, got '\u00e9'\n"
            "utf8.obj:1:5: error: expected a finite number, got 'nan'\n");
}

TEST(ObjSyntax, LenientFormsOfTheFormatLoad) {
  // Relative indices count back from the last vertex above the face; forward ones are allowed.
  World absolute = imported("absolute.obj", triangle + "f 1 2 3\n");
  World relative = imported("relative.obj", triangle + "f -3 -2 -1\nv 5 5 5\n");
  World forward = imported("forward.obj", "f 1 2 3\n" + triangle);
  for (const World* w : {&relative, &forward}) {
    ASSERT_EQ(w->meshes().size(), 1u);
    EXPECT_EQ(w->meshes()[0]->positions, absolute.meshes()[0]->positions);
    EXPECT_EQ(w->meshes()[0]->indices, absolute.meshes()[0]->indices);
  }
  // Comments, tabs, a '+' sign, w, a vertex colour, a lone u, and a number too small for a
  // double, which underflows to 0 as tinyobjloader reads it.
  World lenient = imported("lenient.obj",
                           "# a comment\n"
                           "v\t0 0 0 1  # origin\n"
                           "v +1 0 1e-400\n"
                           "v 0 1 0 0.5 0.5 0.5\n"
                           "vt 0.25\n"
                           "f 1/1 2/1 3/1\n");
  ASSERT_EQ(lenient.meshes().size(), 1u);
  const MeshData& m = *lenient.meshes()[0];
  ASSERT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.positions[1], glm::vec3(1, 0, 0));
  EXPECT_EQ(m.uvs[0], glm::vec2(0.25f, 1.0f));  // v defaults to 0, flipped to a top-left origin
}

TEST(ObjSyntax, MaterialLibrariesOutsideTheFolderAreRefused) {
  write_variant("../outside.mtl", "newmtl stolen\nKd 1 0 0\n");
  EXPECT_EQ(refusal("up.obj", "mtllib ../outside.mtl\n" + triangle + "f 1 2 3\n"),
            ":1:8: error: the material library '../outside.mtl' is outside the OBJ file's folder");
  EXPECT_EQ(refusal("commented.obj", "mtllib cube.mtl # ../outside.mtl\n" + triangle + "f 1 2 3\n"),
            ":1:17: error: a comment may not follow mtllib's file names (tinyobjloader reads its words as file "
            "names); put it on a line of its own");
  // tinyobjloader drops the backslashes that this check keeps: its reader refuses the name.
  EXPECT_EQ(refusal("escaped.obj", "mtllib \\.\\./outside.mtl\n" + triangle + "f 1 2 3\n"),
            ": error: the material library '../outside.mtl' is outside the OBJ file's folder");
  // A name that stays inside is read from the folder.
  write_variant("cube.mtl", read_bytes(fixture("cube.mtl")));
  EXPECT_EQ(imported("inside.obj", "mtllib ./cube.mtl\n" + triangle + "f 1 2 3\n").materials().size(), 2u);
}

// The error of importing a triangle whose MTL library holds `mtl`, after the library's name.
std::string mtl_refusal(const std::string& mtl) {
  std::string library = write_variant("checked.mtl", mtl);
  std::string obj = write_variant("uses_checked.obj", "mtllib checked.mtl\nusemtl m\n" + triangle + "f 1 2 3\n");
  World w;
  std::string message = error_of([&] { import_obj(w, obj); });
  std::string name = folder_of(library) + "/checked.mtl";
  EXPECT_EQ(message.rfind(name, 0), 0u) << message;
  return message.substr(std::min(message.size(), name.size()));
}

TEST(ObjSyntax, MalformedMaterialNumbersAreRefused) {
  EXPECT_EQ(mtl_refusal("newmtl m\nKd 0.5\n"), ":2:1: error: 'Kd' needs r g b; got 1 number");
  EXPECT_EQ(mtl_refusal("newmtl m\nKd nan 0 0\n"), ":2:4: error: expected a finite number of at least 0, got 'nan'");
  EXPECT_EQ(mtl_refusal("newmtl m\nKe 1 -2 0\n"), ":2:6: error: expected a finite number of at least 0, got '-2'");
  EXPECT_EQ(mtl_refusal("newmtl m\nd 1.5\n"), ":2:3: error: expected a number from 0 to 1, got '1.5'");
  EXPECT_EQ(mtl_refusal("newmtl m\n  Ns inf\n"), ":2:6: error: expected a finite number of at least 0, got 'inf'");
  // The same statements well formed, with a comment and a tab, load.
  write_variant("good.mtl", "newmtl m\nKd 0.25 0.5 1 # blue\nKe\t0 0 2\nd 0.5\nNs 10\nPm 1\n");
  World w = imported("good_mtl.obj", "mtllib good.mtl\nusemtl m\n" + triangle + "f 1 2 3\n");
  ASSERT_EQ(w.materials().size(), 1u);
  EXPECT_EQ(w.materials()[0].base_color, glm::vec4(0.25f, 0.5f, 1.0f, 0.5f));
  EXPECT_EQ(w.materials()[0].emissive, glm::vec3(0, 0, 2));
  EXPECT_FLOAT_EQ(w.materials()[0].metalness, 1.0f);
}

// Random edits of the cube (characters replaced by ones that matter to OBJ, inserted or
// deleted) either load or throw a SceneError; nothing else escapes, and under the sanitizer
// build no edit reads out of bounds.
TEST(ObjSyntax, RandomEditsLoadOrFailWithASceneError) {
  const std::string cube = read_bytes(fixture("cube.obj"));
  const std::string alphabet = " \t\r\n/-+.#0123456789eEnaif";
  std::mt19937_64 rng(20261202);
  auto pick = [&](size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng); };
  // Beside a copy of cube.mtl, so that the edits that keep its name still find it.
  write_variant("cube.mtl", read_bytes(fixture("cube.mtl")));
  size_t loaded = 0, refused = 0;
  for (int round = 0; round < 300; ++round) {
    std::string text = cube;
    for (int edit = 0, edits = 1 + static_cast<int>(pick(3)); edit < edits; ++edit) {
      size_t at = pick(text.size());
      switch (pick(3)) {
        case 0:
          text[at] = alphabet[pick(alphabet.size())];
          break;
        case 1:
          text.insert(at, 1, alphabet[pick(alphabet.size())]);
          break;
        default:
          text.erase(at, 1);
      }
    }
    std::string path = write_variant("mutated.obj", text);
    World w;
    try {
      import_obj(w, path);
      ++loaded;
    } catch (const SceneError&) {
      ++refused;
    }
  }
  EXPECT_GT(loaded, 0u);  // most edits in comments, names and digits leave a valid file
  EXPECT_GT(refused, 0u);
}

}  // namespace
}  // namespace lg
