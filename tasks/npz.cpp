// NumPy's .npz: a ZIP archive, stored without compression, of one .npy file an array. The .npy
// layout is NumPy's format 1.0 (numpy.lib.format: the magic, a little-endian header length and a
// Python dict literal padded so that the data starts on a 64-byte boundary); the ZIP layout is
// PKWARE's APPNOTE (local headers, a central directory, its end record). Written here rather
// than through libzip, which writes through temporary files of its own beside the target that our
// whole-or-nothing writer and Ctrl-C's clean-up would not know of; zlib gives the CRC-32.
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "tasks/arrays.hpp"

namespace tasks {
namespace {

static_assert(std::endian::native == std::endian::little,
              "arrays are written as the machine holds them: little-endian");

void put16(std::string& out, std::uint32_t v) {
  out += static_cast<char>(v & 0xff);
  out += static_cast<char>((v >> 8) & 0xff);
}
void put32(std::string& out, std::uint32_t v) {
  put16(out, v & 0xffff);
  put16(out, v >> 16);
}

// The .npy header: magic, version 1.0, its length and the dict, padded to 64 bytes in all.
std::string npyHeader(const NamedArray& a) {
  std::string descr = a.type == ArrayType::Float64 ? "<f8"
                      : a.type == ArrayType::Int64 ? "<i8"
                                                   : "<U" + std::to_string(a.width);
  std::string dict = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': (" +
                     std::to_string(a.length) + ",), }";
  const std::size_t unpadded = 10 + dict.size() + 1;  // + the closing newline
  dict.append((64 - unpadded % 64) % 64, ' ');
  dict += '\n';
  std::string header = "\x93NUMPY";
  header += '\x01';
  header += '\x00';
  put16(header, static_cast<std::uint32_t>(dict.size()));
  return header + dict;
}

// NumPy's text type is UTF-32: each ASCII character as four bytes.
std::string utf32(const NamedArray& a) {
  std::string out(a.bytes.size() * 4, '\0');
  for (std::size_t i = 0; i < a.bytes.size(); ++i) out[4 * i] = a.bytes[i];
  return out;
}

std::uint32_t crcOf(std::uint32_t crc, std::string_view bytes) {
  // zlib takes a length of 32 bits: a column past 4 GiB goes in pieces.
  constexpr std::size_t kPiece = std::size_t{1} << 30;
  for (std::size_t at = 0; at < bytes.size(); at += kPiece) {
    const std::size_t n = std::min(kPiece, bytes.size() - at);
    crc = static_cast<std::uint32_t>(
        crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + at), static_cast<uInt>(n)));
  }
  return crc;
}

// One member of the archive: its .npy header and data, which the local header must know the
// CRC and size of before they are written.
struct Member {
  std::string name;
  std::string header;
  std::string owned;  ///< the data when converted (text); else empty
  std::string_view data;
  std::uint32_t crc = 0;
  std::uint64_t size = 0;
  std::uint64_t offset = 0;  ///< of its local header
};

Member memberOf(const NamedArray& a) {
  Member m;
  m.name = a.name + ".npy";
  m.header = npyHeader(a);
  if (a.type == ArrayType::Text) {
    m.owned = utf32(a);
    m.data = m.owned;
  } else {
    m.data = a.bytes;
  }
  m.crc = crcOf(crcOf(static_cast<std::uint32_t>(crc32(0, nullptr, 0)), m.header), m.data);
  m.size = m.header.size() + m.data.size();
  return m;
}

// An array of text from words (the names and units of the arrays), owning its bytes.
struct TextArray {
  std::string bytes;
  NamedArray array;
};
TextArray textArray(const std::string& name, const std::vector<std::string>& words) {
  std::size_t width = 1;
  for (const std::string& w : words) width = std::max(width, w.size());
  TextArray t;
  for (const std::string& w : words) t.bytes += w + std::string(width - w.size(), '\0');
  t.array.name = name;
  t.array.type = ArrayType::Text;
  t.array.length = words.size();
  t.array.width = width;
  return t;
}

// The fields both headers share: version needed 2.0, no flags, stored, a fixed time (1980-01-01
// 00:00, so that a run written twice gives the same bytes), CRC and sizes, the name's length.
void common(std::string& out, const Member& m) {
  put16(out, 20);
  put16(out, 0);
  put16(out, 0);
  put16(out, 0);
  put16(out, (0 << 9) | (1 << 5) | 1);
  put32(out, m.crc);
  put32(out, static_cast<std::uint32_t>(m.size));
  put32(out, static_cast<std::uint32_t>(m.size));
  put16(out, static_cast<std::uint32_t>(m.name.size()));
}

}  // namespace

rb::Status writeNpz(std::ostream& out, std::span<const NamedArray> arrays,
                    const std::string& path) {
  std::vector<std::string> names, units;
  for (const NamedArray& a : arrays) {
    names.push_back(a.name);
    units.push_back(a.unit);
  }
  TextArray columns = textArray("columns", names), unit_array = textArray("units", units);
  columns.array.bytes = columns.bytes;
  unit_array.array.bytes = unit_array.bytes;
  std::vector<Member> members;
  for (const NamedArray& a : arrays) members.push_back(memberOf(a));
  members.push_back(memberOf(columns.array));
  members.push_back(memberOf(unit_array.array));

  std::uint64_t at = 0;
  for (Member& m : members) {
    m.offset = at;
    at += 30 + m.name.size() + m.size;
  }
  std::uint64_t directory = 0;
  for (const Member& m : members) directory += 46 + m.name.size();
  if (at + directory + 22 > std::numeric_limits<std::uint32_t>::max())
    return rb::Status::fail(path + ": " + std::to_string((at + directory) >> 20) +
                            " MiB of arrays; a .npz holds at most 4 GiB: give a lower rate, or "
                            "write .h5 or .csv");
  for (const Member& m : members) {
    std::string local;
    put32(local, 0x04034b50);
    common(local, m);
    put16(local, 0);  // no extra field
    out << local << m.name << m.header;
    out.write(m.data.data(), static_cast<std::streamsize>(m.data.size()));
  }
  std::string end;
  for (const Member& m : members) {
    put32(end, 0x02014b50);
    put16(end, 20);  // made by: version 2.0, MS-DOS attributes
    common(end, m);
    put16(end, 0);  // extra field
    put16(end, 0);  // comment
    put16(end, 0);  // disk
    put16(end, 0);  // internal attributes
    put32(end, 0);  // external attributes
    put32(end, static_cast<std::uint32_t>(m.offset));
    end += m.name;
  }
  put32(end, 0x06054b50);
  put16(end, 0);
  put16(end, 0);
  put16(end, static_cast<std::uint32_t>(members.size()));
  put16(end, static_cast<std::uint32_t>(members.size()));
  put32(end, static_cast<std::uint32_t>(directory));
  put32(end, static_cast<std::uint32_t>(at));
  put16(end, 0);  // comment
  out << end;
  return {};
}

}  // namespace tasks
