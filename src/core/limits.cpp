#include <illum/limits.h>

#include <algorithm>

namespace illum {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr double kSanitizerSlowdown = 3;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr double kSanitizerSlowdown = 3;
#else
constexpr double kSanitizerSlowdown = 1;
#endif
#else
constexpr double kSanitizerSlowdown = 1;
#endif

}  // namespace

std::uint64_t Limits::memoryBytesFor(std::uint64_t fileBytes) const {
  constexpr std::uint64_t MiB = std::uint64_t(1) << 20;
  // A petabyte is no limit on any machine, and sums and products with it cannot overflow: larger
  // values of --max-memory (2^43 MiB and up once wrapped to 0) mean "unlimited".
  constexpr std::uint64_t kUnlimitedMiB = std::uint64_t(1) << 30;
  if (maxMemoryMiB != 0) return std::min(maxMemoryMiB, kUnlimitedMiB) * MiB;
  // A reader needs memory in proportion to what it reads; compressed formats (glb, zae, 3mf)
  // expand, so the factor is generous, and small files get a floor that any sane one fits in.
  return 512 * MiB + 32 * fileBytes;
}

double Limits::secondsFor(std::uint64_t fileBytes) const {
  if (maxSeconds > 0) return maxSeconds;
  // Every file of assimp's test models reads in under 0.8 s; a big binary mesh reads at several
  // MiB per second. Sanitizer builds run several times slower.
  return kSanitizerSlowdown * (1.5 + 0.5 * double(fileBytes) / double(std::uint64_t(1) << 20));
}

std::string withThousands(std::uint64_t n) {
  std::string s = std::to_string(n);
  for (int i = int(s.size()) - 3; i > 0; i -= 3) s.insert(std::size_t(i), ",");
  return s;
}

}  // namespace illum
