// krom_font: builds the HLE kernel's ROM kanji font from Debian's xfonts-shinonome PCF font
// (shnmk14.pcf.gz, the public-domain Shinonome 14-dot JIS X 0208 gothic). Writes a C++ source
// with the glyphs in the BIOS ROM's layout (psx-spx "BIOS Character Sets"): charset 2 (Shift-JIS
// 8140h-84BEh, JIS rows 1-8) then charset 3 (889Fh-9872h, JIS rows 16-47), each the font's
// glyphs of those rows in code order, 15 rows of 16 pixels (2 bytes a row, leftmost pixel in bit 7
// of the first byte), and the Shift-JIS code of each glyph.
// Usage: krom_font FONT.pcf.gz OUT.cpp. The PCF layout is the X11 one (tables of contents,
// METRICS, BITMAPS, BDF_ENCODINGS; each table's first word gives its byte/bit order and padding).
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr uint32_t kMetrics = 4, kBitmaps = 8, kEncodings = 32;
constexpr uint32_t kCompressedMetrics = 0x100, kByteMsb = 4, kBitMsb = 8;
constexpr int kCellW = 16, kCellH = 15;

struct Glyph {
  int lsb, rsb, width, ascent, descent;
  uint32_t offset;
};

struct Pcf {
  std::vector<uint8_t> data;
  std::vector<Glyph> glyphs;
  std::vector<uint8_t> bitmaps;
  uint32_t bitmap_format = 0;
  std::vector<uint16_t> index;  // JIS code (byte1 << 8 | byte2) -> glyph, 0xFFFF none
  int min2 = 0, max2 = 0, min1 = 0, max1 = 0;
};

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what); }

std::vector<uint8_t> read_gz(const std::string& path) {
  gzFile f = gzopen(path.c_str(), "rb");
  if (!f) fail("cannot open " + path);
  std::vector<uint8_t> out;
  uint8_t buf[65536];
  int n;
  while ((n = gzread(f, buf, sizeof buf)) > 0) out.insert(out.end(), buf, buf + n);
  gzclose(f);
  if (n < 0) fail(path + ": not a readable gzip file");
  return out;
}

// A reader over one table, in the byte order its format word gives.
struct Reader {
  const std::vector<uint8_t>& d;
  uint32_t pos;
  bool msb;
  uint32_t u(int bytes) {
    if (pos + bytes > d.size()) fail("PCF table runs past the end of the file at offset " + std::to_string(pos));
    uint32_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= uint32_t(d[pos + i]) << 8 * (msb ? bytes - 1 - i : i);
    pos += bytes;
    return v;
  }
  int s16() { return int16_t(u(2)); }
};

// Finds a table; returns a reader positioned after its format word (stored little-endian).
Reader table(const Pcf& pcf, uint32_t type, uint32_t& format) {
  Reader toc{pcf.data, 0, false};
  if (toc.u(4) != 0x70636601) fail("not a PCF font (bad magic at offset 0)");
  uint32_t count = toc.u(4);
  for (uint32_t i = 0; i < count; ++i) {
    uint32_t t = toc.u(4), f = toc.u(4), size = toc.u(4), offset = toc.u(4);
    (void)f, (void)size;
    if (t != type) continue;
    Reader r{pcf.data, offset, false};
    format = r.u(4);
    r.msb = format & kByteMsb;
    return r;
  }
  fail("PCF font has no table of type " + std::to_string(type));
}

void read_metrics(Pcf& pcf) {
  uint32_t format;
  Reader r = table(pcf, kMetrics, format);
  bool compressed = format & kCompressedMetrics;
  uint32_t n = compressed ? r.u(2) : r.u(4);
  for (uint32_t i = 0; i < n; ++i) {
    Glyph g{};
    if (compressed) {
      g.lsb = int(r.u(1)) - 0x80, g.rsb = int(r.u(1)) - 0x80, g.width = int(r.u(1)) - 0x80;
      g.ascent = int(r.u(1)) - 0x80, g.descent = int(r.u(1)) - 0x80;
    } else {
      g.lsb = r.s16(), g.rsb = r.s16(), g.width = r.s16(), g.ascent = r.s16(), g.descent = r.s16();
      r.u(2);  // attributes
    }
    pcf.glyphs.push_back(g);
  }
}

// Bitmaps, normalised to most significant bit and byte first (as FreeType's PCF reader does:
// bits are reversed when the bit order is LSB first, bytes swapped within each scan unit when the
// byte order differs from the bit order).
void read_bitmaps(Pcf& pcf) {
  uint32_t format;
  Reader r = table(pcf, kBitmaps, format);
  uint32_t n = r.u(4);
  if (n != pcf.glyphs.size()) fail("PCF bitmap count differs from the metrics count");
  for (auto& g : pcf.glyphs) g.offset = r.u(4);
  uint32_t sizes[4];
  for (auto& s : sizes) s = r.u(4);
  uint32_t size = sizes[format & 3];
  if (r.pos + size > pcf.data.size()) fail("PCF bitmaps run past the end of the file");
  pcf.bitmaps.assign(pcf.data.begin() + r.pos, pcf.data.begin() + r.pos + size);
  pcf.bitmap_format = format;
  if (!(format & kBitMsb))
    for (auto& b : pcf.bitmaps) {
      uint8_t v = 0;
      for (int i = 0; i < 8; ++i) v |= ((b >> i) & 1) << (7 - i);
      b = v;
    }
  const uint32_t unit = 1u << ((format >> 4) & 3);
  if (bool(format & kByteMsb) != bool(format & kBitMsb) && unit > 1)
    for (size_t i = 0; i + unit <= pcf.bitmaps.size(); i += unit)
      for (uint32_t k = 0; k < unit / 2; ++k) std::swap(pcf.bitmaps[i + k], pcf.bitmaps[i + unit - 1 - k]);
}

void read_encodings(Pcf& pcf) {
  uint32_t format;
  Reader r = table(pcf, kEncodings, format);
  pcf.min2 = r.s16(), pcf.max2 = r.s16(), pcf.min1 = r.s16(), pcf.max1 = r.s16();
  r.s16();  // default char
  const uint32_t n = uint32_t(pcf.max2 - pcf.min2 + 1) * uint32_t(pcf.max1 - pcf.min1 + 1);
  for (uint32_t i = 0; i < n; ++i) pcf.index.push_back(uint16_t(r.u(2)));
}

int glyph_of(const Pcf& pcf, int jis) {
  int b1 = jis >> 8, b2 = jis & 0xFF;
  if (b1 < pcf.min1 || b1 > pcf.max1 || b2 < pcf.min2 || b2 > pcf.max2) return -1;
  uint16_t g = pcf.index[(b1 - pcf.min1) * (pcf.max2 - pcf.min2 + 1) + (b2 - pcf.min2)];
  return g == 0xFFFF || g >= pcf.glyphs.size() ? -1 : g;
}

// One glyph in the ROM's 16x15 cell: the font's ascent line at the cell's row `baseline`.
void cell(const Pcf& pcf, const Glyph& g, int baseline, int jis, std::vector<uint8_t>& out) {
  const uint32_t pad = 1u << (pcf.bitmap_format & 3);
  const uint32_t stride = ((uint32_t(g.rsb - g.lsb) + 8 * pad - 1) / (8 * pad)) * pad;
  uint16_t rows[kCellH] = {};
  for (int y = 0; y < g.ascent + g.descent; ++y)
    for (int x = 0; x < g.rsb - g.lsb; ++x) {
      size_t at = g.offset + y * stride + x / 8;
      if (at >= pcf.bitmaps.size()) fail("glyph bitmap outside the bitmap table");
      if (!((pcf.bitmaps[at] >> (7 - x % 8)) & 1)) continue;
      int cx = g.lsb + x, cy = baseline - g.ascent + y;
      if (cx < 0 || cx >= kCellW || cy < 0 || cy >= kCellH) {
        char msg[96];
        std::snprintf(msg, sizeof msg, "JIS %04X: a pixel falls outside the 16x15 ROM cell", jis);
        fail(msg);
      }
      rows[cy] |= uint16_t(0x8000 >> cx);
    }
  for (uint16_t r : rows) out.push_back(uint8_t(r >> 8)), out.push_back(uint8_t(r));
}

// JIS X 0208 row/cell (21h-7Eh each) to Shift-JIS.
int sjis(int jis) {
  int j1 = jis >> 8, j2 = jis & 0xFF;
  int lead = (j1 + 1) / 2 + (j1 <= 0x5E ? 0x70 : 0xB0);
  int trail = j1 & 1 ? j2 + (j2 >= 0x60 ? 0x20 : 0x1F) : j2 + 0x7E;
  return lead << 8 | trail;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: krom_font FONT.pcf.gz OUT.cpp\n");
    return 2;
  }
  try {
    Pcf pcf;
    pcf.data = read_gz(argv[1]);
    read_metrics(pcf);
    read_bitmaps(pcf);
    read_encodings(pcf);
    // Charset 2: JIS rows 1-8; charset 3: rows 16-47 (psx-spx's Shift-JIS ranges).
    const int rows[2][2] = {{0x21, 0x28}, {0x30, 0x4F}};
    std::vector<int> codes[2];
    int ascent = 0;
    for (int set = 0; set < 2; ++set)
      for (int r = rows[set][0]; r <= rows[set][1]; ++r)
        for (int c = 0x21; c <= 0x7E; ++c)
          if (int g = glyph_of(pcf, r << 8 | c); g >= 0) {
            codes[set].push_back(r << 8 | c);
            ascent = std::max(ascent, pcf.glyphs[g].ascent);
          }
    // The ROM has room for 524 and 2965 glyphs (psx-spx's charset addresses, 30 bytes a glyph).
    if (codes[0].size() > 524 || codes[1].size() > 2965) fail("more glyphs than the ROM's charsets hold");
    std::vector<uint8_t> rom;
    for (auto& set : codes)
      for (int jis : set) cell(pcf, pcf.glyphs[glyph_of(pcf, jis)], ascent, jis, rom);

    std::ofstream out(argv[2]);
    out << "// Generated by tools/krom_font from " << argv[1] << " (Debian's xfonts-shinonome, public domain).\n"
        << "#include \"core/bios/hle_font.h\"\n\nnamespace psx::krom {\n\n"
        << "const u32 kCharset2Glyphs = " << codes[0].size() << ", kCharset3Glyphs = " << codes[1].size() << ";\n\n"
        << "const u16 kCodes[] = {";
    size_t n = 0;
    for (auto& set : codes)
      for (int jis : set) out << (n++ % 12 ? " " : "\n    ") << "0x" << std::hex << sjis(jis) << ",";
    out << "\n};\n\nconst u8 kGlyphs[] = {";
    for (size_t i = 0; i < rom.size(); ++i) out << (i % 20 ? " " : "\n    ") << "0x" << std::hex << int(rom[i]) << ",";
    out << "\n};\n\n}  // namespace psx::krom\n";
    if (!out) fail(std::string("cannot write ") + argv[2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "krom_font: %s: %s\n", argv[1], e.what());
    return 1;
  }
  return 0;
}
