#include "core/io/ply_mesh_reader.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "core/io/depth_png.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {

constexpr std::size_t kMaxHeaderBytes = 64 * 1024;
constexpr std::size_t kMaxElements = 16, kMaxProperties = 64;
constexpr std::uint64_t kMaxCount = std::uint64_t(std::numeric_limits<std::int32_t>::max());

enum class Type { I8, U8, I16, U16, I32, U32, F32, F64 };

struct TypeInfo {
  const char* name;
  const char* alias;
  Type type;
  int size;
  double lo, hi;  // integer range (floats: infinite)
};

constexpr double kInf = std::numeric_limits<double>::infinity();
const TypeInfo kTypes[] = {
    {"char", "int8", Type::I8, 1, -128, 127},
    {"uchar", "uint8", Type::U8, 1, 0, 255},
    {"short", "int16", Type::I16, 2, -32768, 32767},
    {"ushort", "uint16", Type::U16, 2, 0, 65535},
    {"int", "int32", Type::I32, 4, -2147483648.0, 2147483647.0},
    {"uint", "uint32", Type::U32, 4, 0, 4294967295.0},
    {"float", "float32", Type::F32, 4, -kInf, kInf},
    {"double", "float64", Type::F64, 8, -kInf, kInf},
};

const TypeInfo& info(Type t) { return kTypes[static_cast<int>(t)]; }
bool is_integer(Type t) { return t != Type::F32 && t != Type::F64; }

struct Property {
  std::string name;
  bool is_list = false;
  Type type = Type::F32;        // scalar type, or the list's item type
  Type count_type = Type::U8;   // lists only
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> props;
  int find(const std::string& n) const {
    for (std::size_t i = 0; i < props.size(); ++i)
      if (props[i].name == n) return static_cast<int>(i);
    return -1;
  }
};

struct Header {
  bool ascii = false;
  std::vector<Element> elements;
  std::vector<std::string> comments;
  std::size_t body_offset = 0;
};

class Parser {
 public:
  Parser(const std::uint8_t* data, std::size_t size, std::string name)
      : data_(data), size_(size), name_(std::move(name)) {}

  [[noreturn]] void fail(const std::string& problem) const { throw InputError(name_, problem); }

  Header parse_header() const;
  PlyMesh parse_body(const Header& h);

 private:
  Type parse_type(const std::string& word, const std::string& line) const {
    for (const TypeInfo& t : kTypes)
      if (word == t.name || word == t.alias) return t.type;
    fail("corrupt PLY header: unknown property type in '" + line + "'");
  }

  // Binary or ascii value of type `t` at the cursor; throws at the end of the data.
  double next(Type t, const char* what);
  double next_binary(Type t, const char* what);
  double next_ascii(Type t, const char* what);

  const std::uint8_t* data_;
  std::size_t size_;
  std::string name_;
  bool ascii_ = false;
  std::size_t pos_ = 0;
};

std::string clip(const std::string& s) { return s.size() > 60 ? s.substr(0, 60) + "..." : s; }

Header Parser::parse_header() const {
  // The header is text up to "end_header\n"; refuse before looking at anything else.
  const std::size_t limit = std::min(size_, kMaxHeaderBytes);
  if (size_ < 4 || std::memcmp(data_, "ply", 3) != 0 || (data_[3] != '\n' && data_[3] != '\r'))
    fail("is not a PLY file (no 'ply' magic line)");
  Header h;
  bool have_format = false, done = false;
  std::size_t pos = 0;
  for (int line_no = 0; pos < limit && !done; ++line_no) {
    const void* nl = std::memchr(data_ + pos, '\n', limit - pos);
    if (!nl) break;
    const std::size_t end = static_cast<const std::uint8_t*>(nl) - data_;
    std::string line(reinterpret_cast<const char*>(data_ + pos), end - pos);
    pos = end + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_no == 0) continue;  // "ply"
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "comment" || key == "obj_info") {
      h.comments.push_back(line.size() > 8 ? line.substr(8) : std::string());
    } else if (key == "format") {
      std::string kind, version;
      words >> kind >> version;
      if (kind == "ascii") h.ascii = true;
      else if (kind == "binary_little_endian") h.ascii = false;
      else if (kind == "binary_big_endian") fail("binary_big_endian PLY is not supported (ascii or binary_little_endian)");
      else fail("corrupt PLY header: unknown format '" + clip(kind) + "'");
      if (version != "1.0") fail("unsupported PLY version '" + clip(version) + "'");
      have_format = true;
    } else if (key == "element") {
      Element e;
      std::string count;
      words >> e.name >> count;
      std::uint64_t n = 0;
      const auto r = std::from_chars(count.data(), count.data() + count.size(), n);
      if (e.name.empty() || r.ec != std::errc() || r.ptr != count.data() + count.size())
        fail("corrupt PLY header: bad element line '" + clip(line) + "'");
      if (n > kMaxCount) fail("absurd element count " + count + " for '" + clip(e.name) + "'");
      for (const Element& o : h.elements)
        if (o.name == e.name) fail("corrupt PLY header: element '" + clip(e.name) + "' declared twice");
      if (h.elements.size() >= kMaxElements) fail("corrupt PLY header: too many elements");
      e.count = n;
      h.elements.push_back(std::move(e));
    } else if (key == "property") {
      if (h.elements.empty()) fail("corrupt PLY header: property before any element");
      Element& e = h.elements.back();
      Property p;
      std::string word;
      words >> word;
      if (word == "list") {
        std::string count_type, item_type;
        words >> count_type >> item_type;
        p.is_list = true;
        p.count_type = parse_type(count_type, clip(line));
        p.type = parse_type(item_type, clip(line));
        if (!is_integer(p.count_type) || !is_integer(p.type))
          fail("corrupt PLY header: list types must be integers in '" + clip(line) + "'");
      } else {
        p.type = parse_type(word, clip(line));
      }
      words >> p.name;
      if (p.name.empty()) fail("corrupt PLY header: property without a name");
      if (e.find(p.name) >= 0)
        fail("corrupt PLY header: property '" + clip(p.name) + "' declared twice in '" + clip(e.name) + "'");
      if (e.props.size() >= kMaxProperties) fail("corrupt PLY header: too many properties");
      e.props.push_back(std::move(p));
    } else if (key == "end_header") {
      done = true;
    } else if (!key.empty()) {
      fail("corrupt PLY header: unexpected line '" + clip(line) + "'");
    }
  }
  if (!done) fail("truncated or corrupt PLY header (no end_header within " +
                  std::to_string(kMaxHeaderBytes / 1024) + " KiB)");
  if (!have_format) fail("corrupt PLY header: no format line");
  for (const Element& e : h.elements)
    if (e.props.empty() && e.count > 0) fail("corrupt PLY header: element '" + clip(e.name) + "' has no properties");
  h.body_offset = pos;

  // Smallest possible body for these counts (a list holds at least its count): refuse a
  // header that promises more than the file holds, before allocating anything.
  const std::uint64_t body = size_ - pos;
  std::uint64_t need = 0;
  for (const Element& e : h.elements) {
    std::uint64_t per_item = 0;
    for (const Property& p : e.props)
      per_item += h.ascii ? 2 : info(p.is_list ? p.count_type : p.type).size;
    need += e.count * per_item;  // <= 2^31 * 512: no overflow
  }
  if (h.ascii && need > 0) need -= 1;  // the last value needs no separator
  if (need > body)
    fail("truncated PLY: header promises at least " + std::to_string(need) + " bytes of data, file has " +
         std::to_string(body));
  return h;
}

double Parser::next_binary(Type t, const char* what) {
  const int n = info(t).size;
  if (size_ - pos_ < static_cast<std::size_t>(n))
    fail(std::string("truncated PLY: data ends inside ") + what);
  const std::uint8_t* p = data_ + pos_;
  pos_ += n;
  std::uint64_t u = 0;
  for (int i = n - 1; i >= 0; --i) u = (u << 8) | p[i];  // little endian, whatever the host
  switch (t) {
    case Type::I8: return static_cast<std::int8_t>(u);
    case Type::U8: return static_cast<std::uint8_t>(u);
    case Type::I16: return static_cast<std::int16_t>(u);
    case Type::U16: return static_cast<std::uint16_t>(u);
    case Type::I32: return static_cast<std::int32_t>(u);
    case Type::U32: return static_cast<std::uint32_t>(u);
    case Type::F32: {
      const auto bits = static_cast<std::uint32_t>(u);
      float f;
      std::memcpy(&f, &bits, 4);
      return f;
    }
    case Type::F64: {
      double d;
      std::memcpy(&d, &u, 8);
      return d;
    }
  }
  return 0;
}

double Parser::next_ascii(Type t, const char* what) {
  const auto space = [&](std::uint8_t c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (pos_ < size_ && space(data_[pos_])) ++pos_;
  const std::size_t start = pos_;
  while (pos_ < size_ && !space(data_[pos_])) ++pos_;
  if (start == pos_) fail(std::string("truncated PLY: data ends inside ") + what);
  const char* b = reinterpret_cast<const char*>(data_ + start);
  const char* e = reinterpret_cast<const char*>(data_ + pos_);
  const std::string token(b, std::min<std::size_t>(e - b, 24));
  if (is_integer(t)) {
    long long v = 0;
    const auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e || v < info(t).lo || v > info(t).hi)
      fail(std::string("bad value '") + token + "' for a " + info(t).name + " in " + what);
    return static_cast<double>(v);
  }
  double v = 0;
  const auto r = std::from_chars(b, e, v);
  if (r.ec != std::errc() || r.ptr != e) fail(std::string("bad number '") + token + "' in " + what);
  return v;
}

double Parser::next(Type t, const char* what) { return ascii_ ? next_ascii(t, what) : next_binary(t, what); }

// Integer-valued property in range [lo, hi] (floats must hold a whole number).
std::int64_t whole(const Parser& p, double v, double lo, double hi, const std::string& what) {
  if (!(v >= lo && v <= hi) || v != std::floor(v))
    p.fail(what + " is " + (std::isfinite(v) ? std::to_string(v) : std::string("not finite")) +
           " (expected a whole number in " + std::to_string(static_cast<long long>(lo)) + ".." +
           std::to_string(static_cast<long long>(hi)) + ")");
  return static_cast<std::int64_t>(v);
}

// Three values as floats; a non-finite value or one outside float's range (a double) is refused
// (the conversion itself would be undefined).
Eigen::Vector3f finite_vector(const Parser& p, const std::vector<double>& v, int a, int b, int c,
                              const std::string& what) {
  constexpr double kMax = std::numeric_limits<float>::max();
  Eigen::Vector3f out;
  const int idx[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    const double x = v[idx[k]];
    if (!(std::abs(x) <= kMax)) p.fail(what + " is not finite (or out of float range)");
    out[k] = static_cast<float>(x);
  }
  return out;
}

PlyMesh Parser::parse_body(const Header& h) {
  ascii_ = h.ascii;
  pos_ = h.body_offset;
  const Element* vertex_el = nullptr;
  for (const Element& e : h.elements)
    if (e.name == "vertex") vertex_el = &e;
  if (!vertex_el) fail("PLY has no vertex element");
  const int ix = vertex_el->find("x"), iy = vertex_el->find("y"), iz = vertex_el->find("z");
  if (ix < 0 || iy < 0 || iz < 0) fail("PLY vertices have no x, y, z properties");
  for (const Element& e : h.elements)
    for (const Property& p : e.props)
      if (p.is_list && &e == vertex_el) fail("PLY vertex property '" + clip(p.name) + "' is a list");

  PlyMesh m;
  m.comments = h.comments;
  for (const Element& e : h.elements) {
    const bool is_vertex = &e == vertex_el, is_face = e.name == "face";
    const auto role = [&](const char* n) { return e.find(n); };
    int normal[3] = {role("nx"), role("ny"), role("nz")};
    int colour[3] = {role("red"), role("green"), role("blue")};
    int vlabel = role("plane") >= 0 ? role("plane") : role("label");
    int list = role("vertex_indices") >= 0 ? role("vertex_indices") : role("vertex_index");
    int flabel = role("label"), fwall = role("wall");
    const bool has_normals = is_vertex && normal[0] >= 0 && normal[1] >= 0 && normal[2] >= 0;
    const bool has_colours = is_vertex && colour[0] >= 0 && colour[1] >= 0 && colour[2] >= 0;
    if (is_face) {
      if (list < 0 || !e.props[list].is_list) fail("PLY face element has no vertex_indices list");
      if (flabel >= 0 && e.props[flabel].is_list) flabel = -1;
      if (fwall >= 0 && e.props[fwall].is_list) fwall = -1;
    }
    if (is_vertex) {
      m.vertices.reserve(e.count);
      if (has_normals) m.normals.reserve(e.count);
      if (has_colours) m.colors.reserve(e.count);
      if (vlabel >= 0) m.vertex_labels.reserve(e.count);
    } else if (is_face) {
      m.triangles.reserve(e.count);
    }
    const std::string where = is_vertex ? "vertex " : is_face ? "face " : "element '" + clip(e.name) + "' item ";
    std::vector<double> values(e.props.size());
    std::int64_t poly[kMaxPlyPolygonVertices];
    for (std::uint64_t i = 0; i < e.count; ++i) {
      int poly_n = 0;
      for (std::size_t k = 0; k < e.props.size(); ++k) {
        const Property& p = e.props[k];
        if (!p.is_list) {
          values[k] = next(p.type, is_vertex ? "a vertex" : is_face ? "a face" : "an element");
          continue;
        }
        const double count = next(p.count_type, "a list length");
        const bool indices = is_face && static_cast<int>(k) == list;
        const double max_len = indices ? kMaxPlyPolygonVertices : 1e6;
        const auto n = whole(*this, count, indices ? 3 : 0, max_len,
                             "PLY " + where + std::to_string(i) + ": list '" + clip(p.name) + "' length");
        for (std::int64_t j = 0; j < n; ++j) {
          const double v = next(p.type, "a list");
          if (indices) poly[poly_n++] = whole(*this, v, 0, kMaxCount, "PLY face " + std::to_string(i) + ": vertex index");
        }
      }
      if (is_vertex) {
        m.vertices.push_back(finite_vector(*this, values, ix, iy, iz, "PLY vertex " + std::to_string(i) + " position"));
        if (has_normals)
          m.normals.push_back(finite_vector(*this, values, normal[0], normal[1], normal[2],
                                            "PLY vertex " + std::to_string(i) + " normal"));
        if (has_colours) {
          std::array<std::uint8_t, 3> c{};
          for (int q = 0; q < 3; ++q)
            c[q] = static_cast<std::uint8_t>(whole(*this, values[colour[q]], 0, 255,
                                                   "PLY vertex " + std::to_string(i) + " colour"));
          m.colors.push_back(c);
        }
        if (vlabel >= 0)
          m.vertex_labels.push_back(static_cast<std::int32_t>(
              whole(*this, values[vlabel], -2147483648.0, 2147483647.0, "PLY vertex " + std::to_string(i) + " label")));
      } else if (is_face) {
        const auto label_of = [&](int k, const char* what) {
          return static_cast<std::int32_t>(whole(*this, values[k], -2147483648.0, 2147483647.0,
                                                 "PLY face " + std::to_string(i) + " " + what));
        };
        const std::int32_t fl = flabel >= 0 ? label_of(flabel, "label") : 0;
        const std::int32_t fw = fwall >= 0 ? label_of(fwall, "wall") : 0;
        for (int j = 1; j + 1 < poly_n; ++j) {  // fan triangulation
          m.triangles.push_back({std::int32_t(poly[0]), std::int32_t(poly[j]), std::int32_t(poly[j + 1])});
          if (flabel >= 0) m.face_labels.push_back(fl);
          if (fwall >= 0) m.face_walls.push_back(fw);
        }
      }
    }
  }
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (std::int32_t v : m.triangles[t])
      if (static_cast<std::size_t>(v) >= m.vertices.size())
        fail("PLY triangle " + std::to_string(t) + " refers to vertex " + std::to_string(v) + " of " +
             std::to_string(m.vertices.size()));
  return m;
}

}  // namespace

PlyMesh parse_ply_mesh(const std::uint8_t* data, std::size_t size, const std::string& name) {
  if (size > kMaxPlyFileBytes) throw InputError(name, "file is too large (" + std::to_string(size) + " bytes)");
  Parser parser(data, size, name);
  const Header h = parser.parse_header();
  return parser.parse_body(h);
}

PlyMesh read_ply_mesh(const std::string& path) {
  const std::vector<std::uint8_t> bytes = read_file_bytes(path, kMaxPlyFileBytes);
  return parse_ply_mesh(bytes.data(), bytes.size(), path);
}

}  // namespace tunnelmap
