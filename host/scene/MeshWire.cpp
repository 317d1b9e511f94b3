#include "MeshWire.hpp"

#include <cstring>

#include "common/InputError.hpp"

namespace arp::host {

namespace {
constexpr char kMagic[8] = {'A', 'R', 'P', 'M', 'E', 'S', 'H', '1'};

template <class T>
void put(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}
template <class V>
void put_array(std::string& out, const std::vector<V>& v) {
  put(out, static_cast<uint64_t>(v.size()));
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(V));
}

struct Reader {
  const std::string& bytes;
  const std::string& source;
  size_t pos = 0;
  template <class T>
  T get() {
    if (bytes.size() - pos < sizeof(T)) throw InputError(source, "", "the model importer's output is truncated");
    T v;
    std::memcpy(&v, bytes.data() + pos, sizeof v);
    pos += sizeof v;
    return v;
  }
  template <class V>
  std::vector<V> get_array() {
    const auto n = get<uint64_t>();
    if (n > (bytes.size() - pos) / sizeof(V)) throw InputError(source, "", "the model importer's output is truncated");
    std::vector<V> v(static_cast<size_t>(n));
    std::memcpy(v.data(), bytes.data() + pos, v.size() * sizeof(V));
    pos += v.size() * sizeof(V);
    return v;
  }
};
}  // namespace

std::string encode_mesh(const Mesh& m) {
  std::string out(kMagic, sizeof kMagic);
  put_array(out, m.positions);
  put_array(out, m.uvs);
  put_array(out, m.indices);
  return out;
}

Mesh decode_mesh(const std::string& bytes, const std::string& source) {
  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw InputError(source, "", "the model importer gave no mesh");
  Reader r{bytes, source, sizeof kMagic};
  Mesh m;
  m.positions = r.get_array<glm::dvec3>();
  m.uvs = r.get_array<glm::dvec2>();
  m.indices = r.get_array<uint32_t>();
  if (r.pos != bytes.size()) throw InputError(source, "", "the model importer's output has trailing bytes");
  return m;
}

}  // namespace arp::host
