// Rendering a scene: visibility (nearest triangle per pixel centre), texture coordinates,
// footprint and filtering. render_ref is the float reference (double throughout) that the C model
// and the RTL are measured against.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "texunit/image.hpp"
#include "texunit/scene.hpp"

namespace tu::render {

struct PixelRecord {
  int x = 0, y = 0;
  int object = -1;
  double u = 0, v = 0;  // level-0 texels
  double lod = 0;       // mip level used (EWA: the walk's level; trilinear: the blend position)
  int texels = 0;       // texels read
  double aniso = 1;          // footprint anisotropy major / minor (after the material's clamp)
  double footprint_lod = 0;  // log2 of the clamped minor axis, in [0, coarsest level] (`texunit plan`)
  img::Rgba8 color;
};

struct Frame {
  img::Rgba8Image image;
  std::vector<PixelRecord> pixels;  // covered pixels, row-major
};

// Index of the nearest triangle hit at each pixel centre: object and triangle, or -1.
struct Cover {
  int object = -1, triangle = -1;
};
std::vector<Cover> visibility(const scene::Scene& s);

// Float reference render. `filter`, when given, overrides every material's filter.
Frame render_ref(const scene::Scene& s, std::optional<scene::Filter> filter = {});

// |a - b| per pixel (max over RGB) mapped to a blue-red heat map, `full_scale` levels = red.
img::Rgba8Image error_heatmap(const img::Rgba8Image& a, const img::Rgba8Image& b, int full_scale);

// One CSV row per covered pixel: x,y,u,v,lod,texels,r,g,b,a (atomic write).
void write_dump_csv(const std::string& path, const Frame& f);

}  // namespace tu::render
