// libFuzzer target: environment maps. Any bytes must be checked and decoded to a map, or refused
// with an InputError, in bounded time (stb_image's Radiance decoder loops for ever on a run of
// length 0 unless checkRadianceHdr refuses it first); a decoded map must answer lookups.
#include <illum/environment.h>
#include <illum/error.h>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  illum::Limits limits;
  limits.maxPixels = 256 * 256;
  try {
    const illum::EnvironmentMap map =
        illum::EnvironmentMap::decode(std::string(reinterpret_cast<const char*>(data), size), "fuzz.hdr", limits);
    for (const illum::Vec3& d : {illum::Vec3(0, 1, 0), illum::Vec3(0, -1, 0), illum::Vec3(0.6f, 0, -0.8f)})
      (void)map.radiance(d);
  } catch (const illum::InputError&) {
  }
  return 0;
}
