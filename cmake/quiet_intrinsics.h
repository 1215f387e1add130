// Included before every source (CMakeLists.txt): GCC's own x86 intrinsics,
// with two of its warnings off inside them only.
//
// GCC 12's AVX-512 intrinsics build an undefined vector as `__m512d __Y =
// __Y;` (avx512fintrin.h), and once Eigen's reductions and broadcasts are
// inlined GCC reports that line as "may be used uninitialized" (GCC bug
// 105593, fixed in GCC 13): about 2,000 warnings in a build with AVX-512.
// A diagnostic pragma applies where the warning is located, so with the
// intrinsics' header included here between these pragmas, the warnings
// located in it are dropped and those located in this project's code are
// kept. (GCC 12 does not keep the pragmas in a precompiled header, bug
// 64117; this is why the library has none.)
#if defined(__x86_64__) || defined(__i386__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop
#endif
