// Run-time choice of the dense kernels' SIMD level, and the per-thread packing
// workspace the blocked GEMM/SYRK share.
//
// The CPU check follows the Intel SDM (vol. 1, 13.2 and 15.2): a level is
// usable only if CPUID reports the instructions *and* XGETBV reports that the
// OS saves the register state they need (YMM for AVX2, opmask + ZMM for
// AVX-512); a kernel run without the second check would fault on an OS or
// hypervisor that disabled the state.
#include "gab/sparse/dense_kernels.h"

#include <cstdlib>
#include <cstring>

#include "kernels/dense_kernels_internal.h"

#if defined(__x86_64__)
#include <cpuid.h>
#endif

namespace gab {

namespace {

#if defined(__x86_64__)
uint64_t read_xcr0() {
  uint32_t eax = 0;
  uint32_t edx = 0;
  // xgetbv via asm: the _xgetbv intrinsic would need -mxsave on this file.
  __asm__ volatile("xgetbv" : "=a"(eax), "=d"(edx) : "c"(0));
  return (static_cast<uint64_t>(edx) << 32) | eax;
}

SimdLevel detect_simd_level() {
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  if (__get_cpuid(1, &eax, &ebx, &ecx, &edx) == 0) return SimdLevel::kScalar;
  const bool fma = (ecx & (1u << 12)) != 0;
  const bool osxsave = (ecx & (1u << 27)) != 0;
  const bool avx = (ecx & (1u << 28)) != 0;
  if (!fma || !osxsave || !avx) return SimdLevel::kScalar;
  const uint64_t xcr0 = read_xcr0();
  constexpr uint64_t kSseAvxState = 0x6;   // XMM, YMM upper halves
  constexpr uint64_t kAvx512State = 0xE0;  // opmask, ZMM0-15 upper, ZMM16-31
  if ((xcr0 & kSseAvxState) != kSseAvxState) return SimdLevel::kScalar;
  if (__get_cpuid_count(7, 0, &eax, &ebx, &ecx, &edx) == 0) return SimdLevel::kScalar;
  const bool avx2 = (ebx & (1u << 5)) != 0;
  if (!avx2) return SimdLevel::kScalar;
  const bool avx512f = (ebx & (1u << 16)) != 0;
  const bool avx512dq = (ebx & (1u << 17)) != 0;
  const bool avx512vl = (ebx & (1u << 31)) != 0;
  if (avx512f && avx512dq && avx512vl && (xcr0 & kAvx512State) == kAvx512State) {
    return SimdLevel::kAvx512;
  }
  return SimdLevel::kAvx2;
}
#else
SimdLevel detect_simd_level() { return SimdLevel::kScalar; }
#endif

SimdLevel lower(SimdLevel a, SimdLevel b) {
  return static_cast<int>(a) < static_cast<int>(b) ? a : b;
}

// The buffer behind packing_workspace(); one per thread, so concurrent
// factorizations of different fronts never share it.
struct Workspace {
  double* data = nullptr;
  size_t size = 0;  // in doubles
  Workspace() = default;
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;
  ~Workspace() { std::free(data); }
};

}  // namespace

SimdLevel cpu_simd_level() {
  static const SimdLevel level = detect_simd_level();
  return level;
}

const char* simd_level_name(SimdLevel level) {
  switch (level) {
    case SimdLevel::kAvx512:
      return "avx512";
    case SimdLevel::kAvx2:
      return "avx2";
    case SimdLevel::kScalar:
      break;
  }
  return "scalar";
}

SimdLevel simd_level_for_cap(const char* cap) {
  const SimdLevel best = cpu_simd_level();
  if (cap == nullptr) return best;
  if (std::strcmp(cap, "scalar") == 0) return SimdLevel::kScalar;
  if (std::strcmp(cap, "avx2") == 0) return lower(SimdLevel::kAvx2, best);
  if (std::strcmp(cap, "avx512") == 0) return lower(SimdLevel::kAvx512, best);
  return best;
}

const DenseKernels& dense_kernels(SimdLevel level) {
  level = lower(level, cpu_simd_level());
  const DenseKernels* table = nullptr;
  switch (level) {
    case SimdLevel::kAvx512:
      table = dense_detail::avx512_table();
      break;
    case SimdLevel::kAvx2:
      table = dense_detail::avx2_table();
      break;
    case SimdLevel::kScalar:
      break;
  }
  // cpu_simd_level() never exceeds what is compiled in, so table is only
  // null for the scalar level.
  return table != nullptr ? *table : *dense_detail::scalar_table();
}

const DenseKernels& dense_kernels() {
  static const DenseKernels& chosen = dense_kernels(simd_level_for_cap(std::getenv("GAB_SIMD")));
  return chosen;
}

namespace dense_detail {

double* packing_workspace(size_t doubles) {
  thread_local Workspace ws;
  if (doubles <= ws.size) return ws.data;
  // Whole cache lines, so aligned_alloc's size rule holds.
  const size_t want = (doubles + 7) / 8 * 8;
  void* fresh = std::aligned_alloc(64, want * sizeof(double));
  if (fresh == nullptr) return nullptr;  // the caller runs unpacked
  std::free(ws.data);
  ws.data = static_cast<double*>(fresh);
  ws.size = want;
  return ws.data;
}

}  // namespace dense_detail

}  // namespace gab
