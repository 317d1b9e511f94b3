#include "ModelPrecheck.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include "common/InputError.hpp"
#include "common/StrictJson.hpp"
#include "common/WholeNumber.hpp"

namespace arp::host {

namespace {

std::string lower_extension(const std::string& path) {
  const auto dot = path.rfind('.');
  std::string e = dot == std::string::npos ? "" : path.substr(dot + 1);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

std::string read_prefix(const std::string& path, size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string s(n, '\0');
  in.read(s.data(), static_cast<std::streamsize>(n));
  s.resize(static_cast<size_t>(in.gcount()));
  return s;
}

[[noreturn]] void refuse(const std::string& path, const std::string& place, const std::string& why) {
  throw InputError(path, place, why);
}

// n elements of at least `min_bytes` each must fit in `available` bytes.
void check_fits(const std::string& path, const std::string& what, uint64_t n, uint64_t min_bytes, uint64_t available) {
  if (min_bytes > 0 && n > available / min_bytes)
    refuse(path, "header", "declares " + std::to_string(n) + " " + what + " of at least " + std::to_string(min_bytes) +
                               " bytes each, but the file holds only " + std::to_string(available) + " bytes after its header");
}

uint64_t parse_count(const std::string& path, const std::string& place, const std::string& token) {
  if (token.empty() || token.size() > 19 || !std::all_of(token.begin(), token.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    refuse(path, place, "expected a count, got \"" + quoted(token) + "\"");
  return std::stoull(token);
}

// PLY: "element NAME N" lines, each followed by its properties; the data
// needs, per element, at least 2 bytes a value in ASCII ("0 ") or the
// properties' sizes in binary (a list at least its count).
void check_ply(const std::string& path, uint64_t size) {
  const std::string head = read_prefix(path, 1 << 16);
  if (head.rfind("ply", 0) != 0) refuse(path, "line 1", "not a PLY file (no 'ply' magic)");
  // The header: lines up to one that is "end_header" itself (not a line
  // merely containing it -- assimp's reader hangs on such headers).
  size_t end = std::string::npos, data_start = std::string::npos;
  for (size_t at = 0; at < head.size();) {
    const size_t nl = head.find('\n', at);
    if (nl == std::string::npos) break;
    std::string l = head.substr(at, nl - at);
    while (!l.empty() && (l.back() == '\r' || l.back() == ' ' || l.back() == '\t')) l.pop_back();
    if (l == "end_header") {
      end = at;
      data_start = nl + 1;
      break;
    }
    at = nl + 1;
  }
  if (end == std::string::npos) refuse(path, "header", "truncated: no end_header line in the first 64 KB");
  const uint64_t available = size - std::min<uint64_t>(size, data_start);
  static const std::map<std::string, int> kSize{{"char", 1},  {"uchar", 1}, {"int8", 1},   {"uint8", 1},    {"short", 2},
                                                {"ushort", 2}, {"int16", 2}, {"uint16", 2}, {"int", 4},      {"uint", 4},
                                                {"int32", 4},  {"uint32", 4}, {"float", 4}, {"float32", 4}, {"double", 8},
                                                {"float64", 8}};
  std::istringstream lines(head.substr(0, end));
  std::string line, format;
  struct Element {
    std::string name;
    uint64_t count = 0, min_bytes = 0;
  };
  std::vector<Element> elements;
  for (int n = 1; std::getline(lines, line); ++n) {
    std::istringstream ss(line);
    std::string kw;
    ss >> kw;
    const std::string place = "line " + std::to_string(n);
    // (Other lines are let through: real files carry free text, e.g. Blender's "Created by ...".)
    if (kw == "format") ss >> format;
    if (kw == "element") {
      Element e;
      std::string count;
      ss >> e.name >> count;
      e.count = parse_count(path, place, count);
      elements.push_back(e);
    } else if (kw == "property") {
      if (elements.empty()) refuse(path, place, "a property before any element");
      std::string type;
      ss >> type;
      const bool ascii = format == "ascii";
      if (type == "list") ss >> type;  // the count's type: a list is at least its count
      const auto t = kSize.find(type);
      if (t == kSize.end()) refuse(path, place, "unknown property type \"" + quoted(type) + "\"");
      elements.back().min_bytes += ascii ? 2 : static_cast<uint64_t>(t->second);
    }
  }
  if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
    refuse(path, "header", "unknown format \"" + quoted(format) + "\"");
  uint64_t need = 0;
  for (const auto& e : elements) {
    check_fits(path, e.name + " elements", e.count, e.min_bytes, available - std::min(available, need));
    need += e.count * e.min_bytes;
  }
}

// The whitespace-separated words of a line, in place (no copies: a model may be 1 GiB).
std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> w;
  for (size_t at = 0;;) {
    at = line.find_first_not_of(" \t\r", at);
    if (at == std::string_view::npos) return w;
    const size_t end = std::min(line.size(), line.find_first_of(" \t\r", at));
    w.push_back(line.substr(at, end - at));
    at = end;
  }
}

// OFF's faces, each "n i1 .. in" with every index a whole number below the vertex count: assimp's reader takes an
// index beyond the vertices as the last vertex, without a word, where OBJ's and PLY's refuse it. Checked only
// where the header is laid out plainly -- the magic word "OFF" or "COFF" alone on its line or with the three
// counts after it, else the three counts alone on the next line (blank lines and '#' comments skipped) -- and each
// line shorter than 64 KiB; any other layout (counts split over lines, nOFF's dimension, binary) is left to assimp
// as before, rather than guessed at and a valid model refused.
void check_off_faces(const std::string& path, uint64_t nv, uint64_t nf) {
  std::ifstream in(path, std::ios::binary);
  enum class At { magic, counts, vertices, faces } at = At::magic;
  uint64_t line_no = 0, vertices = 0, faces = 0;
  std::vector<char> buf(size_t{1} << 16);  // one line at a time, bounded: a longer one ends the check
  while (faces < nf && in.getline(buf.data(), static_cast<std::streamsize>(buf.size()))) {
    ++line_no;
    const std::vector<std::string_view> w = words_of(std::string_view(buf.data(), std::strlen(buf.data())));
    if (w.empty() || w[0][0] == '#') continue;
    if (at == At::magic) {
      if (w[0] != "OFF" && w[0] != "COFF") return;
      if (w.size() == 1) at = At::counts;
      else if (w.size() == 4) at = nv > 0 ? At::vertices : At::faces;
      else return;
      continue;
    }
    if (at == At::counts) {
      if (w.size() != 3) return;
      at = nv > 0 ? At::vertices : At::faces;
      continue;
    }
    if (at == At::vertices) {
      if (++vertices == nv) at = At::faces;
      continue;
    }
    const std::string place = "line " + std::to_string(line_no);
    const std::string face = "face " + std::to_string(faces++);
    const std::optional<int64_t> n = whole_number(w[0]);
    if (!n || *n < 1) refuse(path, place, face + ": expected its vertex count, got \"" + quoted(std::string(w[0])) + "\"");
    if (static_cast<uint64_t>(*n) >= w.size())
      refuse(path, place, face + ": declares " + std::to_string(*n) + " vertices and lists " + std::to_string(w.size() - 1));
    for (size_t j = 1; j <= static_cast<size_t>(*n); ++j) {
      const std::optional<int64_t> i = whole_number(w[j]);
      if (!i || *i < 0 || static_cast<uint64_t>(*i) >= nv)
        refuse(path, place, face + ": vertex index \"" + quoted(std::string(w[j])) + "\" is not one of the " + std::to_string(nv) +
                                " vertices (0 .. " + std::to_string(nv) + " - 1)");
    }
  }
}

// OFF: "OFF" then "V F E"; at least 3 values a vertex and 4 a face, 2 bytes a value.
void check_off(const std::string& path, uint64_t size) {
  const std::string head = read_prefix(path, 1 << 12);
  std::istringstream in(head);
  std::string magic, v, f;
  in >> magic;
  if (magic.find("OFF") == std::string::npos) refuse(path, "line 1", "not an OFF file (no 'OFF' magic)");
  std::string token;
  std::vector<std::string> counts;
  while (counts.size() < 2 && in >> token) {
    if (token[0] == '#') {
      std::getline(in, token);
      continue;
    }
    counts.push_back(token);
  }
  if (counts.size() < 2) refuse(path, "header", "truncated: no vertex and face counts");
  const uint64_t nv = parse_count(path, "counts", counts[0]), nf = parse_count(path, "counts", counts[1]);
  check_fits(path, "vertices", nv, 6, size);
  check_fits(path, "faces", nf, 8, size - std::min(size, nv * 6));
  check_off_faces(path, nv, nf);
}

// Binary STL: an 80-byte header, a triangle count, 50 bytes a triangle.
void check_stl(const std::string& path, uint64_t size) {
  const std::string head = read_prefix(path, 84);
  if (head.rfind("solid", 0) == 0 && read_prefix(path, 1024).find("facet") != std::string::npos) return;  // ASCII
  if (size < 84) refuse(path, "header", "a binary STL needs 84 bytes of header, the file has " + std::to_string(size));
  uint32_t n = 0;
  std::memcpy(&n, head.data() + 80, 4);
  check_fits(path, "triangles", n, 50, size - 84);
}

// glTF / GLB: every accessor within its buffer view, every view within its
// buffer, every buffer within the bytes the file (or its embedded data) holds.
void check_gltf_json(const std::string& path, const nlohmann::json& j, uint64_t glb_bin_bytes, bool glb) {
  auto arr = [&](const char* k) { return j.contains(k) && j[k].is_array() ? j[k] : nlohmann::json::array(); };
  const auto buffers = arr("buffers"), views = arr("bufferViews"), accessors = arr("accessors");
  auto uint_of = [&](const nlohmann::json& o, const char* k, const std::string& place) -> uint64_t {
    if (!o.contains(k)) return 0;
    if (!o[k].is_number_unsigned() && !(o[k].is_number_integer() && o[k].get<int64_t>() >= 0))
      refuse(path, place + "." + k, "must be a non-negative integer");
    return o[k].get<uint64_t>();
  };
  std::vector<uint64_t> buffer_bytes;
  for (size_t i = 0; i < buffers.size(); ++i) {
    const std::string place = "buffers[" + std::to_string(i) + "]";
    const uint64_t declared = uint_of(buffers[i], "byteLength", place);
    uint64_t held = declared;
    if (!buffers[i].contains("uri")) {
      if (!glb) refuse(path, place, "no uri");
      held = glb_bin_bytes;
    } else if (buffers[i]["uri"].is_string()) {
      const std::string uri = buffers[i]["uri"].get<std::string>();
      const auto comma = uri.find(',');
      if (uri.rfind("data:", 0) == 0 && comma != std::string::npos) held = (uri.size() - comma - 1) / 4 * 3;  // base64
      else {
        struct stat st {};
        const auto slash = path.rfind('/');
        const std::string file = (slash == std::string::npos ? std::string() : path.substr(0, slash + 1)) + uri;
        held = ::stat(file.c_str(), &st) == 0 ? static_cast<uint64_t>(st.st_size) : 0;
      }
    }
    if (declared > held + 3) refuse(path, place + ".byteLength", "is " + std::to_string(declared) + ", but only " + std::to_string(held) + " bytes are there");
    buffer_bytes.push_back(declared);
  }
  std::vector<uint64_t> view_bytes;
  for (size_t i = 0; i < views.size(); ++i) {
    const std::string place = "bufferViews[" + std::to_string(i) + "]";
    const uint64_t b = uint_of(views[i], "buffer", place), off = uint_of(views[i], "byteOffset", place),
                   len = uint_of(views[i], "byteLength", place);
    if (b >= buffer_bytes.size()) refuse(path, place + ".buffer", "names a buffer that does not exist");
    if (off > buffer_bytes[b] || len > buffer_bytes[b] - off) refuse(path, place, "lies outside its buffer");
    view_bytes.push_back(len);
  }
  static const std::map<std::string, uint64_t> kComponents{{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                                          {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
  static const std::map<uint64_t, uint64_t> kBytes{{5120, 1}, {5121, 1}, {5122, 2}, {5123, 2}, {5125, 4}, {5126, 4}};
  for (size_t i = 0; i < accessors.size(); ++i) {
    const std::string place = "accessors[" + std::to_string(i) + "]";
    const auto& a = accessors[i];
    if (!a.contains("bufferView")) continue;  // all zeros: nothing to read
    const uint64_t v = uint_of(a, "bufferView", place), count = uint_of(a, "count", place), off = uint_of(a, "byteOffset", place);
    if (v >= view_bytes.size()) refuse(path, place + ".bufferView", "names a view that does not exist");
    const auto comps = kComponents.find(a.value("type", std::string()));
    const auto bytes = kBytes.find(uint_of(a, "componentType", place));
    if (comps == kComponents.end() || bytes == kBytes.end()) refuse(path, place, "unknown type or componentType");
    const uint64_t element = comps->second * bytes->second;
    check_fits(path, place + " elements", count, element, view_bytes[v] - std::min(view_bytes[v], off));
  }
}

void check_gltf(const std::string& path, uint64_t size, bool glb) {
  if (!glb) {
    check_gltf_json(path, parse_strict_json(read_input_file(path, kMaxModelBytes, "model file"), path), 0, false);
    return;
  }
  const std::string head = read_prefix(path, 20);
  if (head.size() < 20 || head.compare(0, 4, "glTF") != 0) refuse(path, "header", "not a GLB file (no 'glTF' magic)");
  uint32_t total = 0, json_len = 0;
  std::memcpy(&total, head.data() + 8, 4);
  std::memcpy(&json_len, head.data() + 12, 4);
  if (total > size) refuse(path, "header", "declares " + std::to_string(total) + " bytes, the file has " + std::to_string(size));
  if (uint64_t{json_len} + 20 > size) refuse(path, "JSON chunk", "longer than the file");
  const std::string all = read_prefix(path, static_cast<size_t>(std::min<uint64_t>(size, kMaxModelBytes)));
  uint64_t bin = 0;
  const uint64_t bin_at = 20 + uint64_t{json_len};
  if (bin_at + 8 <= all.size()) {
    uint32_t bin_len = 0;
    std::memcpy(&bin_len, all.data() + bin_at, 4);
    bin = std::min<uint64_t>(bin_len, all.size() - bin_at - 8);
  }
  check_gltf_json(path, parse_strict_json(all.substr(20, json_len), path + " (JSON chunk)"), bin, true);
}

}  // namespace

void precheck_model(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw InputError(path, "", "no such model file");
  if (!S_ISREG(st.st_mode)) throw InputError(path, "", "a model must be a regular file");
  const auto size = static_cast<uint64_t>(st.st_size);
  if (size > kMaxModelBytes) throw InputError(path, "", "is " + std::to_string(size) + " bytes, more than the 1 GiB a model may have");
  const std::string ext = lower_extension(path);
  if (ext == "ply") check_ply(path, size);
  else if (ext == "off") check_off(path, size);
  else if (ext == "stl") check_stl(path, size);
  else if (ext == "gltf" || ext == "glb") check_gltf(path, size, ext == "glb");
}

}  // namespace arp::host
