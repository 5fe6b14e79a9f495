#include "graph/json_writer.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <unistd.h>

#include "graph/fault_injection.h"

namespace lg {
namespace {

void write_number(std::string& out, const JsonValue& v) {
  if (!v.number_text().empty()) {
    out += v.number_text();
    return;
  }
  double n = v.as_number();
  if (!std::isfinite(n)) {  // JSON cannot hold these; callers should never produce them
    out += "null";
    return;
  }
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, n);
  out.append(buf, end);
}

bool is_flat(const JsonValue& v) {
  if (!v.is_array() || v.items().size() > 16) return false;
  for (const auto& item : v.items())
    if (item.is_array() || item.is_object()) return false;
  return true;
}

void write(std::string& out, const JsonValue& v, int indent, bool pretty) {
  auto newline = [&](int level) {
    if (!pretty) return;
    out += '\n';
    out.append(static_cast<size_t>(level) * 2, ' ');
  };
  switch (v.kind()) {
    case JsonValue::Kind::null: out += "null"; break;
    case JsonValue::Kind::boolean: out += v.as_bool() ? "true" : "false"; break;
    case JsonValue::Kind::number: write_number(out, v); break;
    case JsonValue::Kind::string: out += json_quote(v.as_string()); break;
    case JsonValue::Kind::array: {
      if (v.items().empty()) {
        out += "[]";
        break;
      }
      bool inline_items = !pretty || is_flat(v);
      out += '[';
      for (size_t k = 0; k < v.items().size(); ++k) {
        if (k) out += inline_items && pretty ? ", " : ",";
        if (!inline_items) newline(indent + 1);
        write(out, v.items()[k], indent + 1, pretty);
      }
      if (!inline_items) newline(indent);
      out += ']';
      break;
    }
    case JsonValue::Kind::object: {
      if (v.members().empty()) {
        out += "{}";
        break;
      }
      out += '{';
      for (size_t k = 0; k < v.members().size(); ++k) {
        if (k) out += ',';
        newline(indent + 1);
        out += json_quote(v.members()[k].first);
        out += pretty ? ": " : ":";
        write(out, v.members()[k].second, indent + 1, pretty);
      }
      newline(indent);
      out += '}';
      break;
    }
  }
}

}  // namespace

std::string json_quote(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + '"';
}

std::string write_json(const JsonValue& value) {
  std::string out;
  write(out, value, 0, true);
  return out + '\n';
}

std::string write_json_compact(const JsonValue& value) {
  std::string out;
  write(out, value, 0, false);
  return out;
}

bool write_file_atomically(const std::string& path, const std::string& text, std::string* error) {
  std::string temp = path + ".tmp-" + std::to_string(::getpid());
  auto fail = [&](const std::string& what) {
    if (error) *error = what + ": " + std::strerror(errno);
    ::unlink(temp.c_str());
    return false;
  };
  int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return fail("cannot create " + temp);
  for (size_t done = 0; done < text.size();) {
    ssize_t n = inject_fault(FaultSite::file_write) ? (errno = ENOSPC, -1)
                                                    : ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ::close(fd);
      return fail("cannot write " + temp);
    }
    done += static_cast<size_t>(n);
  }
  // fsync before rename: otherwise a power loss can leave an empty file under the real name.
  if (::fsync(fd) != 0) {
    ::close(fd);
    return fail("cannot flush " + temp);
  }
  ::close(fd);
  if (::rename(temp.c_str(), path.c_str()) != 0) return fail("cannot replace " + path);
  return true;
}

}  // namespace lg
