// Fuzz target: the scene parser (cmodel/src/scene.cpp) and the set-up of what it accepts.
// Any input either loads or is a SceneError; an accepted scene's triangles set up (float and
// fixed point) or raise a SetupError naming the object. Textures are not built (a PNG path may
// name any file).
#include <cstdint>
#include <string>

#include "texunit/render.hpp"
#include "texunit/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  tu::scene::Scene s;
  try {
    s = tu::scene::parse(text, "fuzz.json", "/nonexistent");
  } catch (const tu::scene::SceneError& e) {
    if (std::string(e.what()).rfind("fuzz.json", 0) != 0) __builtin_trap();  // must name the file
    return 0;
  }
  for (size_t o = 0; o < s.objects.size(); ++o) {
    for (const int side : {1, 4096}) {
      try {
        (void)tu::render::setup_fx(s, o, side, side);
      } catch (const tu::persp::SetupError& e) {
        if (std::string(e.what()).rfind("fuzz.json: object '", 0) != 0) __builtin_trap();
      }
    }
  }
  return 0;
}
