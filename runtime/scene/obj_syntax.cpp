// Implementation of obj_syntax.h: one pass over the lines that counts positions, texture
// coordinates and normals as they are defined, so that relative indices resolve as
// tinyobjloader resolves them; references forward are checked once the file's counts are known.
// MTL files go through the same pass, with their own statements.
#include "runtime/scene/obj_syntax.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <vector>

#include "runtime/scene/contained_path.h"

namespace lg {
namespace {

// What a face corner's indices refer to, in the order of `v/t/n`.
enum Kind { position = 0, uv = 1, normal = 2 };
constexpr std::array<const char*, 3> singular = {"vertex", "texture coordinate", "normal"};
constexpr std::array<const char*, 3> plural = {"vertices", "texture coordinates", "normals"};

std::string count_of(int64_t n, Kind kind) {
  return std::to_string(n) + " " + (n == 1 ? singular[kind] : plural[kind]);
}

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

// A leading '+' (which tinyobjloader accepts and std::from_chars does not) dropped.
std::string_view without_plus(std::string_view s) {
  if (s.size() > 1 && s[0] == '+' && s[1] != '+' && s[1] != '-') s.remove_prefix(1);
  return s;
}

// `s`, all of it, as a decimal number, if a float holds it finitely. One too small for a double
// (1e-400) underflows to 0, as tinyobjloader reads it, and is accepted.
std::optional<double> finite_float(std::string_view s) {
  s = without_plus(s);
  double value = 0.0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (end != s.data() + s.size()) return std::nullopt;
  if (ec == std::errc::result_out_of_range) {
    size_t e = s.find_first_of("eE");
    if (e != std::string_view::npos && e + 1 < s.size() && s[e + 1] == '-') return 0.0;
    return std::nullopt;
  }
  if (ec != std::errc() || !std::isfinite(value) || std::abs(value) > std::numeric_limits<float>::max())
    return std::nullopt;
  return value;
}

// The range a number of a statement must lie in, and how a message says it.
struct Range {
  double min = -std::numeric_limits<double>::infinity(), max = std::numeric_limits<double>::infinity();
  std::string text() const {
    auto number = [](double v) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%g", v);
      return std::string(buf);
    };
    if (std::isfinite(min) && std::isfinite(max)) return "a number from " + number(min) + " to " + number(max);
    if (std::isfinite(min)) return "a finite number of at least " + number(min);
    return "a finite number";
  }
};
constexpr Range any_number{};
constexpr Range non_negative{0.0};
constexpr Range unit_interval{0.0, 1.0};

enum class Format { obj, mtl };

class ObjChecker {
 public:
  ObjChecker(const std::string& path, std::string_view text, Format format)
      : diagnostics_(path), text_(text), format_(format) {}

  Diagnostics run() {
    uint32_t number = 0;
    for (size_t start = 0; start < text_.size() && !stopped_;) {
      size_t end = text_.find_first_of("\r\n", start);
      if (end == std::string_view::npos) end = text_.size();
      line_ = text_.substr(start, end - start);
      line_number_ = ++number;
      check_line();
      start = end + (text_.compare(end, 2, "\r\n") == 0 ? 2 : 1);
    }
    for (const auto& ref : forward_)
      if (!stopped_ && ref.index > defined_[ref.kind])
        error_at(ref.pos, std::string(singular[ref.kind]) + " index " + std::to_string(ref.index) +
                              " is beyond the file's " + count_of(defined_[ref.kind], ref.kind));
    diagnostics_.sort_by_position();
    if (stopped_) diagnostics_.error({}, "", "the check stopped after " + std::to_string(max_obj_errors) + " problems");
    return std::move(diagnostics_);
  }

 private:
  struct Token {
    std::string_view text;
    size_t offset;  // in the line, in bytes
  };
  struct ForwardReference {
    SourcePos pos;
    Kind kind;
    int64_t index;
  };

  // The line's blank-separated words up to a comment (a word that starts with '#').
  void split_line() {
    tokens_.clear();
    comment_ = std::string_view::npos;
    for (size_t i = 0; i < line_.size();) {
      if (is_blank(line_[i])) {
        ++i;
        continue;
      }
      if (line_[i] == '#') {
        comment_ = i;
        break;
      }
      size_t end = i;
      while (end < line_.size() && !is_blank(line_[end])) ++end;
      tokens_.push_back({line_.substr(i, end - i), i});
      i = end;
    }
  }

  void check_line() {
    split_line();
    if (tokens_.empty()) return;
    std::string_view keyword = tokens_[0].text;
    if (format_ == Format::mtl) return check_material_line(keyword);
    if (keyword == "v") {
      check_numbers(tokens_.size() - 1 == 3 || tokens_.size() - 1 == 4 || tokens_.size() - 1 == 6,
                    "a vertex needs x y z, optionally followed by w or by an r g b colour");
      ++defined_[position];
    } else if (keyword == "vt") {
      check_numbers(tokens_.size() >= 2 && tokens_.size() <= 4, "a texture coordinate needs u, optionally v and w");
      ++defined_[uv];
    } else if (keyword == "vn") {
      check_numbers(tokens_.size() - 1 == 3, "a normal needs x y z");
      ++defined_[normal];
    } else if (keyword == "f") {
      check_face();
    } else if (keyword == "mtllib") {
      check_material_libraries();
    }
  }

  // The MTL statements whose numbers become the PBR material (mesh_import.h).
  void check_material_line(std::string_view keyword) {
    const std::string name(keyword);
    if (keyword == "Kd" || keyword == "Ke")
      check_numbers(tokens_.size() - 1 == 3, "'" + name + "' needs r g b", non_negative);
    else if (keyword == "d" || keyword == "Tr" || keyword == "Pm")
      check_numbers(tokens_.size() - 1 == 1, "'" + name + "' needs one number", unit_interval);
    else if (keyword == "Ns")
      check_numbers(tokens_.size() - 1 == 1, "'Ns' needs one number", non_negative);
  }

  // tinyobjloader reads every word after `mtllib` as a file name, a comment's words too.
  void check_material_libraries() {
    if (folder_.empty()) folder_ = folder_of(diagnostics_.file());
    for (size_t i = 1; i < tokens_.size(); ++i)
      if (!inside_folder(folder_ + "/" + std::string(tokens_[i].text), folder_))
        error(tokens_[i].offset,
              "the material library '" + std::string(tokens_[i].text) + "' is outside the OBJ file's folder");
    if (comment_ != std::string_view::npos)
      error(comment_,
            "a comment may not follow mtllib's file names (tinyobjloader reads its words as file names); "
            "put it on a line of its own");
  }

  void check_numbers(bool count_is_right, const std::string& expectation, Range range = any_number) {
    size_t numbers = tokens_.size() - 1;
    if (!count_is_right)
      error(tokens_[0].offset,
            expectation + "; got " + std::to_string(numbers) + (numbers == 1 ? " number" : " numbers"));
    for (size_t i = 1; i < tokens_.size(); ++i) {
      std::optional<double> value = finite_float(tokens_[i].text);
      if (!value || *value < range.min || *value > range.max)
        error(tokens_[i].offset, "expected " + range.text() + ", got '" + std::string(tokens_[i].text) + "'");
    }
  }

  void check_face() {
    size_t corners = tokens_.size() - 1;
    if (corners < 3) return error(tokens_[0].offset, "a face needs at least 3 corners; got " + std::to_string(corners));
    if (corners > max_obj_face_corners)
      return error(tokens_[0].offset, "a face may have at most " + std::to_string(max_obj_face_corners) +
                                          " corners; this one has " + std::to_string(corners));
    for (size_t i = 1; i < tokens_.size(); ++i) check_corner(tokens_[i]);
    if (comment_ != std::string_view::npos)
      error(comment_,
            "a comment may not follow a face's corners (tinyobjloader reads it as index 0); "
            "put it on a line of its own");
  }

  // `v`, `v/t`, `v//n` or `v/t/n`.
  void check_corner(const Token& corner) {
    std::array<std::string_view, 3> parts;
    std::array<size_t, 3> offsets{};
    size_t count = 0;
    bool well_formed = true;
    for (size_t from = 0;;) {
      if (count == parts.size()) {  // a fourth part
        well_formed = false;
        break;
      }
      size_t slash = corner.text.find('/', from);
      parts[count] = corner.text.substr(from, slash == std::string_view::npos ? slash : slash - from);
      offsets[count++] = corner.offset + from;
      if (slash == std::string_view::npos) break;
      from = slash + 1;
    }
    // Only the texture coordinate of `v//n` may be left out.
    for (size_t k = 0; k < count; ++k) well_formed &= !parts[k].empty() || (k == 1 && count == 3);
    if (!well_formed)
      return error(corner.offset,
                   "expected a face corner like 3, 3/1, 3//2 or 3/1/2; got '" + std::string(corner.text) + "'");
    for (size_t k = 0; k < count; ++k)
      if (!parts[k].empty()) check_index(parts[k], offsets[k], static_cast<Kind>(k));
  }

  void check_index(std::string_view text, size_t offset, Kind kind) {
    std::string_view digits = without_plus(text);
    int64_t index = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
    std::string what = std::string(singular[kind]) + " index ";
    if (end != digits.data() + digits.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
      return error(offset,
                   "expected an integer " + std::string(singular[kind]) + " index; got '" + std::string(text) + "'");
    bool negative = !digits.empty() && digits[0] == '-';
    if (ec == std::errc::result_out_of_range || index > std::numeric_limits<int>::max() ||
        index < -int64_t{std::numeric_limits<int>::max()})
      return error(offset, what + std::string(text) + " is out of range");
    if (index == 0) return error(offset, what + "0 is not valid: OBJ counts from 1, or back from -1");
    if (negative && -index > defined_[kind])
      return error(offset, what + std::string(text) + " reaches before the first " + singular[kind] + ": " +
                               count_of(defined_[kind], kind) + " above this line");
    if (!negative && index > defined_[kind]) forward_.push_back({position_of(offset), kind, index});
  }

  // Columns count code points: bytes that do not continue a UTF-8 sequence.
  SourcePos position_of(size_t offset) const {
    uint32_t column = 1;
    for (size_t i = 0; i < offset && i < line_.size(); ++i)
      column += (static_cast<unsigned char>(line_[i]) & 0xC0) != 0x80;
    return {line_number_, column};
  }

  void error(size_t offset, std::string message) { error_at(position_of(offset), std::move(message)); }

  void error_at(SourcePos pos, std::string message) {
    if (diagnostics_.error_count() >= max_obj_errors) {
      stopped_ = true;
      return;
    }
    diagnostics_.error(pos, "", std::move(message));
  }

  Diagnostics diagnostics_;
  std::string_view text_;
  Format format_;
  std::string folder_;  // of the OBJ file, found at its first mtllib
  std::string_view line_;
  uint32_t line_number_ = 0;
  std::vector<Token> tokens_;
  size_t comment_ = std::string_view::npos;  // where the line's comment starts
  std::array<int64_t, 3> defined_{};         // positions, uvs and normals defined so far
  std::vector<ForwardReference> forward_;
  bool stopped_ = false;
};

}  // namespace

Diagnostics check_obj_text(const std::string& path, std::string_view text) {
  return ObjChecker(path, text, Format::obj).run();
}

Diagnostics check_mtl_text(const std::string& path, std::string_view text) {
  return ObjChecker(path, text, Format::mtl).run();
}

}  // namespace lg
