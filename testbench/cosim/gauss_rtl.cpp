// RTL bindings of the Gaussian pixel-model blocks (rtl/gauss/): ports named after the blocks'
// fields (generated glue). The four clip volumes share the clip_p1 block's fields (d -> v).
#include "Vtu_clip_estrin.h"
#include "Vtu_clip_horner.h"
#include "Vtu_clip_p1.h"
#include "Vtu_clip_seq.h"
#include "Vtu_gauss_weight.h"
#include "Vtu_weight_table_1d.h"
#include "Vtu_weight_table_2d.h"
#include "cosim.hpp"

namespace tu::cosim {

std::vector<RtlBlock> rtl_gauss() {
  return {make_rtl<Vtu_clip_p1>("clip_p1", glue::drive_clip_p1<Vtu_clip_p1>, glue::sample_clip_p1<Vtu_clip_p1>),
          make_rtl<Vtu_clip_horner>("clip_horner", glue::drive_clip_horner<Vtu_clip_horner>,
                                    glue::sample_clip_horner<Vtu_clip_horner>),
          make_rtl<Vtu_clip_estrin>("clip_estrin", glue::drive_clip_estrin<Vtu_clip_estrin>,
                                    glue::sample_clip_estrin<Vtu_clip_estrin>),
          make_rtl<Vtu_clip_seq>("clip_seq", glue::drive_clip_seq<Vtu_clip_seq>, glue::sample_clip_seq<Vtu_clip_seq>),
          make_rtl<Vtu_gauss_weight>("gauss_weight", glue::drive_gauss_weight<Vtu_gauss_weight>,
                                     glue::sample_gauss_weight<Vtu_gauss_weight>),
          make_rtl<Vtu_weight_table_1d>("weight_table_1d", glue::drive_weight_table_1d<Vtu_weight_table_1d>,
                                        glue::sample_weight_table_1d<Vtu_weight_table_1d>),
          make_rtl<Vtu_weight_table_2d>("weight_table_2d", glue::drive_weight_table_2d<Vtu_weight_table_2d>,
                                        glue::sample_weight_table_2d<Vtu_weight_table_2d>)};
}

}  // namespace tu::cosim
