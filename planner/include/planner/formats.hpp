// `texunit plan`: the storage format per texture (docs/blocks/texture.md "Formats in the plan"):
// memory in bits per texel and texel bandwidth (bits fetched per pixel) of every format, and the
// cheapest format whose decoded texels meet the scene's PSNR budget.
#pragma once

#include <nlohmann/json.hpp>

#include "texunit/render.hpp"
#include "texunit/scene.hpp"

namespace tu::plan {

// One entry per texture some object samples: every format's bits per texel, pyramid memory (bits,
// tex::stored_bits), bandwidth = texels read per pixel of that texture's objects in `frame` x
// bits per texel (what a texture cache that keeps each fetched line moves; uncached, bc1 reads a
// 64-bit block per texel) and texel PSNR (tex::stored_costs: decoded level 0 against rgba8, sRGB
// as authored); `picked`: the fewest bits per texel with psnr_db >= min_psnr_db (rgba8 always
// qualifies), and what it saves against the authored format. bc1 has no RTL block fetch yet.
nlohmann::json texel_format_plan(const scene::Scene& s, const render::Frame& frame, double min_psnr_db);

}  // namespace tu::plan
