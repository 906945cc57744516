// RTL binding of the object-space per-sample datapath (rtl/objspace/tu_objspace_sample.sv,
// block objspace_sample): one transaction = one sample; and the object-space render through it.
#include "objspace_rtl.hpp"

#include <algorithm>
#include <chrono>
#include <sstream>

#include "Vtu_objspace_sample.h"
#include "cosim.hpp"
#include "objspace/schemes.hpp"
#include "objspace_block.hpp"

namespace tu::cosim {

RtlBlock rtl_objspace_sample() {
  return make_rtl<Vtu_objspace_sample>("objspace_sample", glue::drive_objspace_sample<Vtu_objspace_sample>,
                                       glue::sample_objspace_sample<Vtu_objspace_sample>);
}

ObjspaceRtlRender render_objspace_rtl(const scene::Scene& s, const objspace::Options& opt,
                                      const ObjspaceRtlOptions& ro) {
  static const RtlBlock rtl = rtl_objspace_sample();
  ObjspaceRtlRender r;
  auto datapath = [&](const std::vector<objspace::SampleIn>& in, std::vector<objspace::Splat>& out) {
    std::vector<Row> rows;
    rows.reserve(in.size());
    for (const auto& x : in) rows.push_back(blocks::objspace_sample_in(*x.k, x.i, x.j));
    RunOptions o;
    o.stall_prob = ro.stall_prob;
    o.seed = ro.seed + r.runs;
    const auto t0 = std::chrono::steady_clock::now();
    const auto rr = rtl.run(rows, o);
    r.sim_wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ++r.runs;
    r.sim_cycles += rr.sim_cycles;
    r.hung = r.hung || rr.hung || rr.outputs.size() != rows.size() || rr.extra_outputs != 0;
    for (size_t q = 0; q < in.size(); ++q) {
      ++r.samples;
      const objspace::Splat want = objspace::splat_fx(*in[q].k, in[q].i, in[q].j);
      out[q] = q < rr.outputs.size() ? blocks::objspace_sample_splat(rr.outputs[q]) : objspace::Splat{};
      if (out[q] == want) continue;
      if (r.mismatches++ == 0) {
        std::ostringstream m;
        m << "sample " << r.samples - 1 << " (i " << in[q].i << ", j " << in[q].j << "): rtl x " << out[q].x << " y "
          << out[q].y << " w00 " << out[q].w[0] << ", cmodel x " << want.x << " y " << want.y << " w00 " << want.w[0];
        r.first_mismatch = m.str();
      }
    }
  };
  r.result = objspace::render_cmodel(s, opt, datapath);
  const auto c = objspace::render_cmodel(s, opt);
  const auto& a = r.result.frame.pixels;
  const auto& b = c.frame.pixels;
  r.differing_pixels = a.size() == b.size() ? 0 : std::max(a.size(), b.size());
  for (size_t p = 0; p < std::min(a.size(), b.size()); ++p)
    r.differing_pixels += a[p].x != b[p].x || a[p].y != b[p].y || a[p].texels != b[p].texels ||
                          !(a[p].color == b[p].color);
  const int lat = sched::schedule(objspace::sample_scheme()).latency;
  r.predicted_cycles = r.samples + r.runs * static_cast<uint64_t>(lat);
  return r;
}

}  // namespace tu::cosim
