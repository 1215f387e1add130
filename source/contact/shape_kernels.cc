#include <greentread/contact/shape_kernels.h>

// Compiled with -fopenmp-simd (CMakeLists.txt): the pragmas below let the
// compiler reorder the sums of the dot products to vectorise them; no
// OpenMP run time is involved.

namespace greentread
{
  namespace contact
  {
    namespace
    {
      [[gnu::always_inline]] inline void
      forces_loop(const double *shapes, const std::size_t rows, const std::size_t P,
                  const double *loads, double *forces)
      {
        const double *l0 = loads, *l1 = loads + P, *l2 = loads + 2 * P, *l3 = loads + 3 * P;
        for (std::size_t r = 0; r < rows; ++r)
          {
            const double *s  = shapes + r * P;
            double        a0 = 0., a1 = 0., a2 = 0., a3 = 0.;
#pragma omp simd reduction(+ : a0, a1, a2, a3)
            for (std::size_t p = 0; p < P; ++p)
              {
                a0 += s[p] * l0[p];
                a1 += s[p] * l1[p];
                a2 += s[p] * l2[p];
                a3 += s[p] * l3[p];
              }
            forces[4 * r]     = a0;
            forces[4 * r + 1] = a1;
            forces[4 * r + 2] = a2;
            forces[4 * r + 3] = a3;
          }
      }

      [[gnu::always_inline]] inline void
      add_loop(const double *shapes, const std::size_t rows, const std::size_t P,
               const double *weights, double *out)
      {
        double *u = out, *v = out + P;
        for (std::size_t r = 0; r < rows; ++r)
          {
            const double *s = shapes + r * P;
            const double  w0 = weights[2 * r], w1 = weights[2 * r + 1];
#pragma omp simd
            for (std::size_t p = 0; p < P; ++p)
              {
                u[p] += w0 * s[p];
                v[p] += w1 * s[p];
              }
          }
      }

      __attribute__((target("avx2,fma"))) void
      forces_avx2(const double *shapes, const std::size_t rows, const std::size_t P,
                  const double *loads, double *forces)
      {
        forces_loop(shapes, rows, P, loads, forces);
      }

      __attribute__((target("avx2,fma"))) void
      add_avx2(const double *shapes, const std::size_t rows, const std::size_t P,
               const double *weights, double *out)
      {
        add_loop(shapes, rows, P, weights, out);
      }

      bool
      has_avx2()
      {
        static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
        return yes;
      }
    } // namespace



    void
    modal_forces(const double *shapes, const std::size_t rows, const std::size_t P,
                 const double *loads, double *forces)
    {
      if (has_avx2())
        forces_avx2(shapes, rows, P, loads, forces);
      else
        forces_loop(shapes, rows, P, loads, forces);
    }



    void
    add_weighted_shapes(const double *shapes, const std::size_t rows, const std::size_t P,
                        const double *weights, double *out)
    {
      if (has_avx2())
        add_avx2(shapes, rows, P, weights, out);
      else
        add_loop(shapes, rows, P, weights, out);
    }
  } // namespace contact
} // namespace greentread
