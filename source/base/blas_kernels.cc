#include <greentread/base/blas_kernels.h>

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <strings.h>

namespace greentread
{
  namespace base
  {
    namespace
    {
      /// openblas_get_corename() if the loaded BLAS is OpenBLAS, else null
      /// (looked up at run time: any other BLAS links as well).
      const char *
      openblas_core()
      {
        using Name       = char *(*)();
        const auto named = reinterpret_cast<Name>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
        return named != nullptr ? named() : nullptr;
      }
    } // namespace



    void
    use_native_blas_kernels(char **argv)
    {
      if (std::getenv("OPENBLAS_CORETYPE") != nullptr)
        return;
      const char *core = openblas_core();
      if (core == nullptr || strcasecmp(core, "prescott") != 0)
        return;
      __builtin_cpu_init();
      const char *better = __builtin_cpu_supports("avx512f") ? "SkylakeX" :
                           __builtin_cpu_supports("avx2")    ? "Haswell" :
                                                               nullptr;
      if (better == nullptr)
        return;
      if (setenv("OPENBLAS_CORETYPE", better, 1) != 0)
        return;
      execv("/proc/self/exe", argv);
      // Still here: the image could not be replaced. Go on with Prescott's
      // kernels, and leave the environment as it was for any child.
      unsetenv("OPENBLAS_CORETYPE");
    }



    std::string
    blas_kernels()
    {
      const char *core = openblas_core();
      return core != nullptr ? "OpenBLAS (" + std::string(core) + " kernels)" :
                               std::string("not OpenBLAS");
    }
  } // namespace base
} // namespace greentread
