// The shading stage's set-up (docs/blocks/brdf.md "In the unit"): per covered pixel, the unit
// vectors N (the triangle's interpolated vertex normals, or its face normal, turned towards the
// eye), L (to the point light, or against the directional light's direction) and H = (L + V) / |L + V|
// in double, and the material's and light's colours; the float reference render shades with them
// as they are, the C model and the RTL engine with brdf::shade::quantise'd codes (the shader's
// inputs of the unit's shade port, as the relief stage's tangent view).
#pragma once

#include <vector>

#include "brdf/brdf_shade.hpp"
#include "persp/persp.hpp"
#include "texunit/scene.hpp"

namespace tu::shading {

// The committed full unit's model (rtl/0_pkg/tu_unit_cfg_pkg.sv ShadeModel): the thesis's F_MSH.
inline constexpr brdf::Model kUnitModel = brdf::Model::Msh;
// A model by its brdf::name(); std::invalid_argument otherwise.
brdf::Model model_of(const std::string& name);

class Setup {
 public:
  // `unit_model` stands for every material whose specular model is "auto".
  Setup(const scene::Scene& s, brdf::Model unit_model = kUnitModel);
  bool active() const { return !s_.lights.empty(); }  // a scene without a light is not shaded
  brdf::Model model(int object) const { return obj_[static_cast<size_t>(object)].model; }
  // Float inputs at pixel (x, y) of the object's triangle; false: not shaded (no light, or the
  // ray misses the triangle's plane).
  bool ref_in(const persp::RayCaster& rays, int object, int triangle, int x, int y, brdf::shade::RefIn* out) const;
  // The fixed-point inputs (the shade port word's fields); on = 0 when not shaded.
  brdf::shade::In fx_in(const persp::RayCaster& rays, int object, int triangle, int x, int y) const;

 private:
  struct Obj {
    brdf::Model model = kUnitModel;
    int n = 1;
    double ks[3] = {0, 0, 0};  // specular colour times the light's
    uint64_t ccut = 0;
  };
  const scene::Scene& s_;
  std::vector<Obj> obj_;
};

}  // namespace tu::shading
