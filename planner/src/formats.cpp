// `texunit plan`: texel storage format per texture (formats.hpp).
#include "planner/formats.hpp"

#include <cmath>
#include <set>

#include "texture/texel_format.hpp"

namespace tu::plan {

nlohmann::json texel_format_plan(const scene::Scene& s, const render::Frame& frame, double min_psnr_db) {
  using json = nlohmann::json;
  json out = json::object();
  std::set<std::string> used;
  for (const auto& o : s.objects) used.insert(s.materials.at(o.material).texture);
  for (const std::string& name : used) {
    // Texels read per pixel of the objects that sample this texture.
    double texels = 0;
    size_t px = 0;
    for (const auto& p : frame.pixels)
      if (p.object >= 0 && s.materials.at(s.objects[static_cast<size_t>(p.object)].material).texture == name)
        texels += p.texels, ++px;
    const double per_px = px ? texels / static_cast<double>(px) : 0;
    // The source image: the texture as authored but rgba8 and not sRGB-decoded.
    scene::Scene raw = s;
    const scene::TextureSpec& spec = s.textures.at(name);
    raw.textures.at(name).format = 0;
    raw.textures.at(name).srgb = false;
    raw.textures.at(name).mip_filter = 0;
    const tex::Texture src = scene::build_texture(raw, name);
    const auto costs = tex::stored_costs(name, src.levels[0], spec.addressing, spec.srgb);
    json rows = json::array();
    const tex::StoredCost* pick = nullptr;
    const tex::StoredCost* authored = nullptr;
    for (const auto& c : costs) {
      const bool ok = c.psnr_db >= min_psnr_db;
      if (ok && (!pick || c.bits_per_texel < pick->bits_per_texel)) pick = &c;
      if (static_cast<int>(c.format) == spec.format) authored = &c;
      rows.push_back({{"format", tex::format_name(c.format)},
                      {"bits_per_texel", c.bits_per_texel},
                      {"memory_bits", c.memory_bits},
                      {"bandwidth_bits_per_pixel", per_px * c.bits_per_texel},
                      {"psnr_db", std::isinf(c.psnr_db) ? json("identical") : json(c.psnr_db)},
                      {"meets_budget", ok}});
    }
    out[name] = {{"authored", tex::format_name(authored->format)},
                 {"srgb", spec.srgb},
                 {"texels_per_pixel", per_px},
                 {"formats", rows},
                 {"picked", tex::format_name(pick->format)},
                 {"memory_bits_saved", static_cast<double>(authored->memory_bits) - static_cast<double>(pick->memory_bits)},
                 {"bandwidth_bits_per_pixel_saved", per_px * (authored->bits_per_texel - pick->bits_per_texel)},
                 {"rtl", pick->format == tex::TexelFormat::Bc1
                            ? "tu_texel_port (HasBc1): one 64-bit block read per texel (no block cache: 64 bits on the texel port per texel read)"
                            : "tu_texel_decode"}};
  }
  return out;
}

}  // namespace tu::plan
