#include "core/io/oni_container.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <vector>

#include "core/io/oni_bytes.h"
#include "core/io/oni_payload.h"
#include "core/util/error.h"

namespace tunnelmap::oni {

namespace {

// The layout OpenNI2's recorder writes (its DataRecords.h, format 1.0.1.0: 64-bit positions).
constexpr std::uint64_t kFileHeaderBytes = 24;    // "NI10", version, max timestamp, max node id
constexpr std::uint64_t kRecordHeaderBytes = 28;  // magic, type, node, fields size, payload size, undo position
constexpr std::uint32_t kRecordMagic = 0x0052494E;  // "NIR\0"
// The player decodes a frame into a buffer of 1600x1200x3 bytes and reads a record into one
// of that plus the largest data record header: larger sizes would overflow them.
constexpr std::uint64_t kMaxFrameBytes = 1600ull * 1200 * 3;
constexpr std::uint64_t kMaxRecordBytes = kRecordHeaderBytes + 81 + 8 + 4 + kMaxFrameBytes;
// The player allocates per-node tables by the header's largest node id; real files have a few.
constexpr std::uint32_t kMaxNodeId = 255;
constexpr std::size_t kMaxNodeNameBytes = 80;  // the player's name buffers, terminating NUL included
constexpr std::size_t kMaxPropertyNameBytes = 256;
constexpr std::uint64_t kSeekEntryBytes = 20;  // timestamp, configuration id, position
constexpr std::uint64_t kMaxVideoModes = 256;
constexpr std::uint64_t kVideoModeBytes = 12;  // width, height, fps

// The properties OpenNI2's recorder writes (its fixed list and its table of device
// properties). The player keeps state for each by name and misbehaves on names it does not
// know, so a property under any other name means a damaged file.
bool is_known_property(const std::string& name) {
  static const char* const known[] = {
      "oniOriginalDevice", "oniRequiredFrameSize", "xnIsGenerating", "xnDeviceMaxDepth",
      "xnSupportedMapOutputModesCount", "xnSupportedMapOutputModes", "xnMapOutputMode", "xnSupportedPixelFormats",
      "xnPixelFormat", "oniPixelFormat", "xnFOV", "Cropping", "xnCropping", "Mirror", "xnMirror", "InputFormat",
      "CroppingMode", "WhiteBalancedEnabled", "Gain", "HoleFilter", "RegistrationType", "AGCBin", "ConstShift",
      "PixelSizeFactor", "MaxShift", "ParamCoeff", "ShiftScale", "S2D", "D2S", "ZPD", "ZPPS", "LDDIS", "DCRCDIS",
      "CloseRange", "FastZoomCrop", "PixelRegistration"};
  for (const char* k : known)
    if (name == k) return true;
  return false;
}

enum RecordType : std::uint32_t {
  kIntProperty = 3, kRealProperty = 4, kStringProperty = 5, kGeneralProperty = 6, kNodeRemoved = 7,
  kDataBegin = 8, kStateReady = 9, kNewData = 10, kEnd = 11, kNodeAdded = 13, kSeekTable = 14,
};

enum NodeType : std::uint32_t { kDepthNode = 2, kImageNode = 3, kIrNode = 4 };

struct RecordHeader {
  std::uint64_t position = 0;
  std::uint32_t magic = 0, type = 0, node = 0, fields_bytes = 0, payload_bytes = 0;
  std::uint64_t undo_position = 0;
};

// The fields of one record, read in order; every read is bounded by them.
class Fields {
 public:
  explicit Fields(const std::vector<std::uint8_t>& bytes) : b_(bytes) {}
  bool u32(std::uint32_t& v) { return take(4) && (v = u32_at(at(4)), true); }
  bool u64(std::uint64_t& v) { return take(8) && (v = u64_at(at(8)), true); }
  bool bytes(std::size_t n, const std::uint8_t*& p) { return take(n) && (p = at(n), true); }
  // A length-prefixed string; the player compares it with strcmp, so it must end in a NUL.
  // Bytes outside printable ASCII come back as '?' (no property name the player knows has one).
  bool text(std::size_t max_bytes, std::string& s) {
    std::uint32_t n = 0;
    const std::uint8_t* p = nullptr;
    if (!u32(n) || n == 0 || n > max_bytes || !bytes(n, p) || p[n - 1] != 0) return false;
    s.assign(reinterpret_cast<const char*>(p), std::strlen(reinterpret_cast<const char*>(p)));
    // Names are echoed in messages: a damaged byte must not break the line or the encoding.
    for (char& c : s)
      if (c < 0x20 || c > 0x7e) c = '?';
    return true;
  }
  bool done() const { return pos_ == b_.size(); }

 private:
  bool take(std::size_t n) {
    if (n > b_.size() - pos_) return false;
    pos_ += n;
    return true;
  }
  const std::uint8_t* at(std::size_t n) const { return b_.data() + pos_ - n; }
  const std::vector<std::uint8_t>& b_;
  std::size_t pos_ = 0;
};

struct Node {
  bool valid = false, ready = false;
  std::string name;
  std::uint32_t type = 0;
  Codec codec = Codec::Uncompressed;
  std::uint32_t frames = 0, last_frame = 0;
  std::uint32_t width = 0, height = 0;
  bool cropped = false;
  std::int64_t oni_format = -1, xn_format = -1;
  std::uint64_t required_frame_bytes = 0;
  std::uint64_t video_modes = 0;  // the count the list of supported modes must hold
};

struct SeekTable {
  std::uint32_t node = 0;
  std::uint64_t payload_bytes = 0;
};

struct SeekTableReference {
  std::uint64_t position = 0, node_record = 0;
  std::uint32_t node = 0, frames = 0;
};

// Bytes per pixel of a stream: OpenNI2's pixel format when recorded, else OpenNI 1's.
std::uint32_t bytes_per_pixel(const Node& n) {
  if (n.type == kDepthNode) return 2;
  switch (n.oni_format) {
    case 200: return 3;  // RGB888
    case 201: case 203: case 205: return 2;  // YUV422, GRAY16, YUYV
    case 202: return 1;  // GRAY8
    default: break;
  }
  switch (n.xn_format) {
    case 1: return 3;  // RGB24
    case 2: case 4: return 2;  // YUV422, GRAY16
    case 3: return 1;  // GRAY8
    default: return 0;
  }
}

class RecordingCheck {
 public:
  RecordingCheck(const Bytes& bytes, std::string name, long long max_pixels)
      : bytes_(bytes), name_(std::move(name)), max_pixels_(max_pixels) {}

  void run() {
    check_file_header();
    std::uint64_t pos = kFileHeaderBytes;
    for (;;) {
      const RecordHeader h = read_header(pos);
      check_record(h);
      pos += static_cast<std::uint64_t>(h.fields_bytes) + h.payload_bytes;
      if (h.type == kEnd) break;
    }
    check_totals();
  }

 private:
  [[noreturn]] void fail(const std::string& why) const { throw InputError(name_, "damaged OpenNI recording: " + why); }
  [[noreturn]] void fail_at(const RecordHeader& h, const std::string& why) const {
    fail(why + " (record at byte " + std::to_string(h.position) + ")");
  }

  void check_file_header() {
    const std::size_t have = static_cast<std::size_t>(std::min<std::uint64_t>(bytes_.size(), kFileHeaderBytes));
    bytes_.read(0, have, buf_);
    if (have < 4 || std::memcmp(buf_.data(), "NI10", 4) != 0) fail("no NI10 file marker (not an .oni recording)");
    if (have < kFileHeaderBytes) fail("shorter than its " + std::to_string(kFileHeaderBytes) + "-byte header");
    const std::uint8_t* v = buf_.data() + 4;
    const unsigned maintenance = static_cast<unsigned>(v[2] | (v[3] << 8));
    if (v[0] != 1 || v[1] != 0 || maintenance != 1 || u32_at(v + 4) != 0)
      fail("format version " + std::to_string(v[0]) + "." + std::to_string(v[1]) + "." + std::to_string(maintenance) + "." +
           std::to_string(u32_at(v + 4)) + " is not supported (OpenNI 2 writes 1.0.1.0)");
    max_timestamp_ = u64_at(buf_.data() + 12);
    max_node_id_ = u32_at(buf_.data() + 20);
    if (max_node_id_ > kMaxNodeId) fail("header claims node ids up to " + std::to_string(max_node_id_));
  }

  RecordHeader read_header(std::uint64_t pos) {
    RecordHeader h;
    h.position = pos;
    if (pos == bytes_.size()) fail("ends after byte " + std::to_string(pos) + " without its end record (truncated?)");
    if (bytes_.size() - pos < kRecordHeaderBytes) fail("ends inside the record header at byte " + std::to_string(pos) + " (truncated?)");
    bytes_.read(pos, kRecordHeaderBytes, buf_);
    const std::uint8_t* p = buf_.data();
    h.magic = u32_at(p);
    h.type = u32_at(p + 4);
    h.node = u32_at(p + 8);
    h.fields_bytes = u32_at(p + 12);
    h.payload_bytes = u32_at(p + 16);
    h.undo_position = u64_at(p + 20);
    if (h.magic != kRecordMagic) fail_at(h, "no record marker");
    if (h.fields_bytes < kRecordHeaderBytes || h.fields_bytes > kMaxRecordBytes)
      fail_at(h, "record fields of " + std::to_string(h.fields_bytes) + " bytes");
    const std::uint64_t total = static_cast<std::uint64_t>(h.fields_bytes) + h.payload_bytes;
    if (total > bytes_.size() - pos) fail_at(h, "record of " + std::to_string(total) + " bytes runs past the end of the file (truncated?)");
    if (h.undo_position >= pos) fail_at(h, "record refers forward to byte " + std::to_string(h.undo_position));
    if (h.type != kEnd && h.node > max_node_id_) fail_at(h, "node id " + std::to_string(h.node) + " above the header's " + std::to_string(max_node_id_));
    bytes_.read(pos + kRecordHeaderBytes, h.fields_bytes - kRecordHeaderBytes, fields_);
    return h;
  }

  void check_record(const RecordHeader& h) {
    switch (h.type) {
      case kNodeAdded: return node_added(h);
      case kIntProperty:
      case kRealProperty:
      case kStringProperty:
      case kGeneralProperty: return property(h);
      case kNodeRemoved: return node_removed(h);
      case kDataBegin: return data_begin(h);
      case kStateReady: return state_ready(h);
      case kNewData: return new_data(h);
      case kSeekTable: return seek_table(h);
      case kEnd: return end(h);
      default: fail_at(h, "unknown record type " + std::to_string(h.type));
    }
  }

  void no_fields(const RecordHeader& h) const {
    if (!fields_.empty()) fail_at(h, "unexpected record fields");
  }
  Node& valid_node(const RecordHeader& h) {
    Node& n = nodes_[h.node];
    if (!n.valid) fail_at(h, "record for node " + std::to_string(h.node) + ", which was not added");
    return n;
  }

  void node_added(const RecordHeader& h) {
    Fields f(fields_);
    Node n;
    const std::uint8_t* fourcc = nullptr;
    std::uint64_t min_ts = 0, max_ts = 0, seek_position = 0;
    if (!f.text(kMaxNodeNameBytes, n.name) || !f.u32(n.type) || !f.bytes(4, fourcc) || !f.u32(n.frames) || !f.u64(min_ts) ||
        !f.u64(max_ts) || !f.u64(seek_position) || !f.done())
      fail_at(h, "damaged stream record");
    if (nodes_[h.node].valid) fail_at(h, "node " + std::to_string(h.node) + " added twice");
    if (n.type != kDepthNode && n.type != kImageNode && n.type != kIrNode)
      fail_at(h, "stream '" + n.name + "' of node type " + std::to_string(n.type) + " is not supported");
    if (!codec_from_fourcc(reinterpret_cast<const char*>(fourcc), n.codec))
      fail_at(h, "stream '" + n.name + "' uses an unsupported codec");
    if (n.frames > bytes_.size() / (kRecordHeaderBytes + 12))
      fail_at(h, "stream '" + n.name + "' claims " + std::to_string(n.frames) + " frames, more than the file can hold");
    n.valid = true;
    nodes_[h.node] = n;
    frames_announced_[h.node] = n.frames;
    frames_found_[h.node] = 0;
    if (n.frames > 0 && seek_position != 0) seek_references_.push_back({seek_position, h.position, h.node, n.frames});
  }

  void property(const RecordHeader& h) {
    Node& n = valid_node(h);
    Fields f(fields_);
    std::string name;
    std::uint32_t size = 0;
    const std::uint8_t* data = nullptr;
    if (!f.text(kMaxPropertyNameBytes, name) || !f.u32(size) || !f.bytes(size, data) || !f.done())
      fail_at(h, "damaged property record");
    if (!is_known_property(name)) fail_at(h, "unknown property '" + name + "'");
    const bool number = h.type == kIntProperty || h.type == kRealProperty;
    if (number && size != 8) fail_at(h, "property '" + name + "' of " + std::to_string(size) + " bytes");
    if (h.type == kStringProperty && (size == 0 || data[size - 1] != 0)) fail_at(h, "property '" + name + "' is not a string");
    apply_property(h, n, name, size, data);
  }

  // The properties that size a stream's frames (the player copies fixed-size structs from them).
  void apply_property(const RecordHeader& h, Node& n, const std::string& name, std::uint32_t size, const std::uint8_t* data) {
    const auto sized = [&](std::uint32_t expected) {
      if (size != expected) fail_at(h, "property '" + name + "' of " + std::to_string(size) + " bytes, expected " + std::to_string(expected));
    };
    if (name == "xnMapOutputMode") {
      sized(12);
      n.width = u32_at(data);
      n.height = u32_at(data + 4);
    } else if (name == "xnCropping") {
      sized(12);
      n.cropped = u32_at(data) != 0;
    } else if (name == "xnFOV") {
      sized(16);
    } else if (name == "xnSupportedMapOutputModesCount" && h.type == kIntProperty) {
      n.video_modes = u64_at(data);
      if (n.video_modes > kMaxVideoModes) fail_at(h, "absurd count of " + std::to_string(n.video_modes) + " video modes");
    } else if (name == "xnSupportedMapOutputModes") {
      sized(static_cast<std::uint32_t>(n.video_modes * kVideoModeBytes));
    } else if (name == "oniPixelFormat" && h.type == kIntProperty) {
      n.oni_format = static_cast<std::int64_t>(u64_at(data) & 0xFFFFFFFF);
    } else if (name == "xnPixelFormat" && h.type == kIntProperty) {
      n.xn_format = static_cast<std::int64_t>(u64_at(data) & 0xFFFFFFFF);
    } else if (name == "oniRequiredFrameSize" && h.type == kIntProperty) {
      n.required_frame_bytes = u64_at(data);
    }
  }

  void node_removed(const RecordHeader& h) {
    no_fields(h);
    valid_node(h) = Node();
  }

  void data_begin(const RecordHeader& h) {
    Fields f(fields_);
    std::uint32_t frames = 0;
    std::uint64_t max_ts = 0;
    if (!f.u32(frames) || !f.u64(max_ts) || !f.done()) fail_at(h, "damaged data-begin record");
    valid_node(h);
    data_begun_ = true;
  }

  void state_ready(const RecordHeader& h) {
    no_fields(h);
    valid_node(h).ready = true;
  }

  void new_data(const RecordHeader& h) {
    Node& n = valid_node(h);
    Fields f(fields_);
    std::uint64_t timestamp = 0;
    std::uint32_t frame = 0;
    if (!f.u64(timestamp) || !f.u32(frame) || !f.done()) fail_at(h, "damaged frame record");
    const std::string what = "frame " + std::to_string(frame) + " of stream '" + n.name + "'";
    if (!n.ready) fail_at(h, what + " before the stream is ready");
    if (frame != n.last_frame + 1 || frame > n.frames)
      fail_at(h, what + " out of order (after frame " + std::to_string(n.last_frame) + " of " + std::to_string(n.frames) + ")");
    if (timestamp > max_timestamp_) fail_at(h, what + " is later than the header's last timestamp");
    n.last_frame = frame;
    ++frames_found_[h.node];
    const FrameShape shape = frame_shape(h, n, what);
    bytes_.read(h.position + h.fields_bytes, h.payload_bytes, buf_);
    const std::string problem = payload_problem(n.codec, buf_.data(), buf_.size(), shape);
    if (!problem.empty()) fail_at(h, what + ": " + problem);
  }

  FrameShape frame_shape(const RecordHeader& h, const Node& n, const std::string& what) const {
    FrameShape s{n.width, n.height, bytes_per_pixel(n)};
    if (s.width == 0 || s.height == 0) fail_at(h, what + ": the stream has no resolution");
    if (s.bytes_per_pixel == 0) fail_at(h, what + ": the stream's pixel format is unknown");
    if (n.cropped) fail_at(h, what + ": cropped streams are not supported");
    const std::uint64_t pixels = static_cast<std::uint64_t>(s.width) * s.height;
    const std::uint64_t bytes = pixels * s.bytes_per_pixel;
    if (static_cast<long long>(pixels) > max_pixels_ || bytes > kMaxFrameBytes)
      fail_at(h, what + ": absurd resolution " + std::to_string(s.width) + "x" + std::to_string(s.height));
    if (n.required_frame_bytes != 0 && n.required_frame_bytes != bytes)
      fail_at(h, what + ": the stream's frame size " + std::to_string(n.required_frame_bytes) + " bytes does not match " +
                     std::to_string(s.width) + "x" + std::to_string(s.height) + "x" + std::to_string(s.bytes_per_pixel));
    if (static_cast<std::uint64_t>(h.fields_bytes) + h.payload_bytes > kMaxRecordBytes) fail_at(h, what + " is too large");
    return s;
  }

  void seek_table(const RecordHeader& h) {
    no_fields(h);
    seek_tables_[h.position] = {h.node, h.payload_bytes};
  }

  void end(const RecordHeader& h) {
    if (!data_begun_) fail_at(h, "the recording holds no data");
    for (const auto& [id, n] : nodes_)
      if (n.valid && !n.ready) fail_at(h, "stream '" + n.name + "' never became ready");
  }

  void check_totals() const {
    for (const auto& [id, announced] : frames_announced_)
      if (frames_found_.at(id) != announced)
        fail("node " + std::to_string(id) + " announces " + std::to_string(announced) + " frames but holds " +
             std::to_string(frames_found_.at(id)));
    // The player reads each stream's seek table when the stream is added.
    for (const SeekTableReference& r : seek_references_) {
      const auto t = seek_tables_.find(r.position);
      if (t == seek_tables_.end() || t->second.node != r.node || t->second.payload_bytes != (r.frames + 1ull) * kSeekEntryBytes)
        fail("node " + std::to_string(r.node) + " (record at byte " + std::to_string(r.node_record) +
             ") points at no seek table of its " + std::to_string(r.frames) + " frames");
    }
  }

  const Bytes& bytes_;
  std::string name_;
  long long max_pixels_;
  std::vector<std::uint8_t> buf_, fields_;
  std::uint64_t max_timestamp_ = 0;
  std::uint32_t max_node_id_ = 0;
  bool data_begun_ = false;
  std::map<std::uint32_t, Node> nodes_;
  std::map<std::uint32_t, std::uint32_t> frames_announced_, frames_found_;
  std::map<std::uint64_t, SeekTable> seek_tables_;
  std::vector<SeekTableReference> seek_references_;
};

}  // namespace

void check_recording_file(const std::string& path, long long max_pixels) {
  const FileBytes bytes(path);
  RecordingCheck(bytes, path, max_pixels).run();
}

void check_recording(const std::uint8_t* data, std::size_t size, const std::string& name, long long max_pixels) {
  const MemoryBytes bytes(data, size);
  RecordingCheck(bytes, name, max_pixels).run();
}

}  // namespace tunnelmap::oni
