// Rows of opaque polygons, eight pixels per SSE2 step (SSE2 is part of x86-64, which the
// recompiler already requires): the same pixels as draw_pixel<kTex, kRaw, false> one by one,
// for untextured polygons (flat or Gouraud) and textured ones (raw or modulated, flat or
// Gouraud), dither and mask check included. Texels are fetched one by one (a texture window and
// CLUT per texel), and everything after the fetch is done on eight lanes.
#pragma once
#include <emmintrin.h>

#include <algorithm>
#include <cstring>

#include "gpu/software_renderer_pixel.h"
#include "gpu/triangle_setup.h"

namespace psx::gpu {

// The dither offsets (kDitherMatrix) of eight pixels in a row from x: [y & 3][x & 3][lane].
struct DitherLanes {
  alignas(16) s16 v[4][4][8];
};
constexpr DitherLanes make_dither_lanes() {
  DitherLanes t{};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int i = 0; i < 8; ++i) t.v[y][x][i] = kDitherMatrix[y][(x + i) & 3];
  return t;
}
inline constexpr DitherLanes kDitherLanes = make_dither_lanes();

class RowPainter {
 public:
  // Steps per pixel of the 12-bit fixed-point red, green and blue (0 for a flat polygon). A
  // channel's eight lanes hold value + i * step, wrapping in 32 bits as per-pixel additions do.
  RowPainter(const PixelContext& c, s32 dr, s32 dg, s32 db)
      : ctx_(c), mask_or_(_mm_set1_epi16(static_cast<s16>(c.mask_or))) {
    const s32 steps[3] = {dr, dg, db};
    for (int k = 0; k < 3; ++k) {
      const auto at = [&](u32 i) { return static_cast<s32>(i * static_cast<u32>(steps[k])); };
      offset_lo_[k] = _mm_setr_epi32(at(0), at(1), at(2), at(3));
      offset_hi_[k] = _mm_setr_epi32(at(4), at(5), at(6), at(7));
      step8_[k] = _mm_set1_epi32(at(8));
    }
  }

  // `count` pixels of an untextured polygon's row y from column x, whose first pixel has the
  // channels r, g, b (12-bit fixed point).
  void colour(s32 x, s32 y, u32 count, s32 r, s32 g, s32 b) const {
    const __m128i dither = dither_lanes(x, y);
    Channels c = channels(r, g, b);
    Target t(ctx_, x, y);
    for (u32 i = 0; i < count; i += 8) {
      const __m128i out = pixel(to5(channel8(c, 0), dither), to5(channel8(c, 1), dither), to5(channel8(c, 2), dither));
      store(t, i, count, _mm_or_si128(out, mask_or_), _mm_setzero_si128());
      advance(c);
    }
  }

  // The same for a textured polygon, whose first pixel also has the texture coordinates u, v
  // (12-bit fixed point, stepped by du, dv per pixel). Texel 0000h is transparent; a modulated
  // texel takes colour * texel / 128 with dither, a raw one is drawn as it is; bit 15 is the
  // texel's.
  template <int kTex, bool kRaw>
  void textured(s32 x, s32 y, u32 count, s32 r, s32 g, s32 b, s32 u, s32 v, s32 du, s32 dv) const {
    const __m128i dither = dither_lanes(x, y);
    Channels c = channels(r, g, b);
    Target t(ctx_, x, y);
    u32 tu = static_cast<u32>(u), tv = static_cast<u32>(v);
    for (u32 i = 0; i < count; i += 8) {
      alignas(16) u16 texels[8];
      for (u16& texel : texels) {
        texel = fetch_texel<kTex>(ctx_, (tu >> kFrac) & 0xFF, (tv >> kFrac) & 0xFF);
        tu += static_cast<u32>(du), tv += static_cast<u32>(dv);
      }
      const __m128i texel = load(texels);
      __m128i out = texel;
      if constexpr (!kRaw) {
        const auto modulate = [&](int k, int shift) {
          const __m128i t5 = _mm_and_si128(_mm_srli_epi16(texel, shift), _mm_set1_epi16(0x1F));
          return to5(_mm_srli_epi16(_mm_mullo_epi16(t5, channel8(c, k)), 4), dither);  // at most 494
        };
        out = _mm_or_si128(pixel(modulate(0, 0), modulate(1, 5), modulate(2, 10)),
                           _mm_and_si128(texel, _mm_set1_epi16(static_cast<s16>(kMaskBit))));
      }
      const __m128i transparent = _mm_cmpeq_epi16(texel, _mm_setzero_si128());
      store(t, i, count, _mm_or_si128(out, mask_or_), transparent);
      advance(c);
    }
  }

 private:
  struct Channels {
    __m128i lo[3], hi[3];
  };
  // Where a row's pixels go: from dst, with `room` pixels to the end of the VRAM row.
  struct Target {
    Target(const PixelContext& c, s32 x, s32 y)
        : dst(c.vram + static_cast<u32>(y) * kVramWidth + static_cast<u32>(x)),
          room(kVramWidth - static_cast<u32>(x)) {}
    u16* dst;
    u32 room;
  };

  static __m128i load(const void* p) { return _mm_loadu_si128(static_cast<const __m128i*>(p)); }

  __m128i dither_lanes(s32 x, s32 y) const {
    return ctx_.dither ? load(kDitherLanes.v[y & 3][x & 3]) : _mm_setzero_si128();
  }

  Channels channels(s32 r, s32 g, s32 b) const {
    Channels c;
    const s32 first[3] = {r, g, b};
    for (int k = 0; k < 3; ++k) {
      c.lo[k] = _mm_add_epi32(_mm_set1_epi32(first[k]), offset_lo_[k]);
      c.hi[k] = _mm_add_epi32(_mm_set1_epi32(first[k]), offset_hi_[k]);
    }
    return c;
  }
  void advance(Channels& c) const {
    for (int k = 0; k < 3; ++k) {
      c.lo[k] = _mm_add_epi32(c.lo[k], step8_[k]);
      c.hi[k] = _mm_add_epi32(c.hi[k], step8_[k]);
    }
  }

  // channel() on eight lanes: clamp(v >> 12, 0, 255). Packing to 16 bits saturates, which leaves
  // the clamp unchanged.
  static __m128i channel8(const Channels& c, int k) {
    const __m128i v = _mm_packs_epi32(_mm_srai_epi32(c.lo[k], kFrac), _mm_srai_epi32(c.hi[k], kFrac));
    return _mm_min_epi16(_mm_max_epi16(v, _mm_setzero_si128()), _mm_set1_epi16(255));
  }
  // dither_to_5() on eight lanes: clamp(c + dither, 0, 255) >> 3.
  static __m128i to5(__m128i c, __m128i dither) {
    c = _mm_min_epi16(_mm_max_epi16(_mm_add_epi16(c, dither), _mm_setzero_si128()), _mm_set1_epi16(255));
    return _mm_srli_epi16(c, 3);
  }
  static __m128i pixel(__m128i r5, __m128i g5, __m128i b5) {
    return _mm_or_si128(_mm_or_si128(r5, _mm_slli_epi16(g5, 5)), _mm_slli_epi16(b5, 10));
  }

  // Writes pixels i.. (eight, or the count - i left) where neither `skip` nor the mask check
  // keeps the old one. Lanes past the count keep the pixels there; past the end of the VRAM row
  // (room < 8) the pixels go through a copy.
  void store(const Target& t, u32 i, u32 count, __m128i out, __m128i skip) const {
    const u32 n = std::min(count - i, 8u);
    const __m128i past = _mm_cmpgt_epi16(_mm_set_epi16(8, 7, 6, 5, 4, 3, 2, 1), _mm_set1_epi16(static_cast<s16>(n)));
    const auto merge = [&](u16* at) {
      const __m128i old = load(at);
      __m128i keep = _mm_or_si128(past, skip);
      if (ctx_.check_mask) keep = _mm_or_si128(keep, _mm_srai_epi16(old, 15));  // bit 15 set: kept
      const __m128i merged = _mm_or_si128(_mm_and_si128(keep, old), _mm_andnot_si128(keep, out));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(at), merged);
    };
    if (t.room - i >= 8) return merge(t.dst + i);
    u16 part[8] = {};
    std::memcpy(part, t.dst + i, n * sizeof(u16));
    merge(part);
    std::memcpy(t.dst + i, part, n * sizeof(u16));
  }

  const PixelContext& ctx_;
  __m128i mask_or_;
  __m128i offset_lo_[3], offset_hi_[3], step8_[3];
};

}  // namespace psx::gpu
