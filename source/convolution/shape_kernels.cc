#include <greentread/convolution/shape_kernels.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

// Compiled with -fopenmp-simd (CMakeLists.txt): the pragmas below let the
// compiler reorder the sums of the dot products to vectorise them; no
// OpenMP run time is involved.

namespace greentread
{
  namespace convolution
  {
    namespace
    {
      // The products run in the shapes' precision: for float shapes the
      // loads come rounded to float (by the caller, once per step), the
      // weights are rounded once per call, each dot
      // product (one row, P terms) and each call's sum (at most 128 rows)
      // is formed in float, and the call's sum is added in double.
      template <unsigned int N, typename T>
      [[gnu::always_inline]] inline void
      forces_loop(const T          *shapes,
                  const std::size_t rows,
                  const std::size_t P,
                  const T          *loads,
                  double           *forces)
      {
        const T *l0 = loads, *l1 = loads + (N > 1 ? P : 0), *l2 = loads + (N > 2 ? 2 * P : 0),
                *l3 = loads + (N > 3 ? 3 * P : 0);
        for (std::size_t r = 0; r < rows; ++r)
          {
            const T *s  = shapes + r * P;
            T        a0 = 0, a1 = 0, a2 = 0, a3 = 0;
#pragma omp simd reduction(+ : a0, a1, a2, a3)
            for (std::size_t p = 0; p < P; ++p)
              {
                a0 += s[p] * l0[p];
                if constexpr (N > 1)
                  a1 += s[p] * l1[p];
                if constexpr (N > 2)
                  a2 += s[p] * l2[p];
                if constexpr (N > 3)
                  a3 += s[p] * l3[p];
              }
            double *f = forces + N * r;
            f[0]      = a0;
            if constexpr (N > 1)
              f[1] = a1;
            if constexpr (N > 2)
              f[2] = a2;
            if constexpr (N > 3)
              f[3] = a3;
          }
      }

      // One load vector: four rows at a time, so that four independent sums
      // hide the latency of the additions (one row's sum alone is a chain of
      // P / width dependent FMAs). Returns the rows done.
      template <typename T>
      [[gnu::always_inline]] inline std::size_t
      forces_four_rows(const T          *shapes,
                       const std::size_t rows,
                       const std::size_t P,
                       const T          *l0,
                       double           *forces)
      {
        std::size_t r = 0;
        for (; r + 4 <= rows; r += 4)
          {
            const T *s0 = shapes + r * P, *s1 = s0 + P, *s2 = s1 + P, *s3 = s2 + P;
            T        a0 = 0, a1 = 0, a2 = 0, a3 = 0;
#pragma omp simd reduction(+ : a0, a1, a2, a3)
            for (std::size_t p = 0; p < P; ++p)
              {
                a0 += s0[p] * l0[p];
                a1 += s1[p] * l0[p];
                a2 += s2[p] * l0[p];
                a3 += s3[p] * l0[p];
              }
            forces[r]     = a0;
            forces[r + 1] = a1;
            forces[r + 2] = a2;
            forces[r + 3] = a3;
          }
        return r;
      }

      template <typename T>
      [[gnu::always_inline]] inline void
      forces_any(const T           *shapes,
                 const std::size_t  rows,
                 const std::size_t  P,
                 const T           *l,
                 const unsigned int n_loads,
                 double            *forces)
      {
        switch (n_loads)
          {
            case 1:
              {
                const std::size_t done = forces_four_rows(shapes, rows, P, l, forces);
                return forces_loop<1>(shapes + done * P, rows - done, P, l, forces + done);
              }
            case 2:
              return forces_loop<2>(shapes, rows, P, l, forces);
            case 3:
              return forces_loop<3>(shapes, rows, P, l, forces);
            case 4:
              return forces_loop<4>(shapes, rows, P, l, forces);
            default:
              throw std::logic_error("modal_forces: " + std::to_string(n_loads) +
                                     " load vectors; allowed: 1 to 4");
          }
      }

      // C = 1: u alone; C = 2: u and v. Four rows at a time: u and v are
      // read and written once per four rows.
      template <unsigned int C, typename T>
      [[gnu::always_inline]] inline void
      add_rows(const T          *shapes,
               const std::size_t rows,
               const std::size_t P,
               const double     *weights,
               T                *u,
               T                *v)
      {
        std::size_t r = 0;
        for (; r + 4 <= rows; r += 4)
          {
            const T *s0 = shapes + r * P, *s1 = s0 + P, *s2 = s1 + P, *s3 = s2 + P;
            const T  x0 = T(weights[2 * r]), x1 = T(weights[2 * r + 2]), x2 = T(weights[2 * r + 4]),
                    x3 = T(weights[2 * r + 6]);
            const T y0 = T(weights[2 * r + 1]), y1 = T(weights[2 * r + 3]),
                    y2 = T(weights[2 * r + 5]), y3 = T(weights[2 * r + 7]);
#pragma omp simd
            for (std::size_t p = 0; p < P; ++p)
              {
                const T a = s0[p], b = s1[p], c = s2[p], d = s3[p];
                u[p] += x0 * a + x1 * b + x2 * c + x3 * d;
                if constexpr (C > 1)
                  v[p] += y0 * a + y1 * b + y2 * c + y3 * d;
              }
          }
        for (; r < rows; ++r)
          {
            const T *s  = shapes + r * P;
            const T  w0 = T(weights[2 * r]), w1 = T(weights[2 * r + 1]);
#pragma omp simd
            for (std::size_t p = 0; p < P; ++p)
              {
                u[p] += w0 * s[p];
                if constexpr (C > 1)
                  v[p] += w1 * s[p];
              }
          }
      }

      template <typename T>
      [[gnu::always_inline]] inline void
      add_loop(const T           *shapes,
               const std::size_t  rows,
               const std::size_t  P,
               const double      *weights,
               const unsigned int n_out,
               double            *out)
      {
        if constexpr (std::is_same_v<T, double>)
          {
            if (n_out == 1)
              add_rows<1>(shapes, rows, P, weights, out, out);
            else
              add_rows<2>(shapes, rows, P, weights, out, out + P);
          }
        else
          {
            thread_local std::vector<float> sum;
            sum.assign(2 * P, 0.f);
            if (n_out == 1)
              add_rows<1>(shapes, rows, P, weights, sum.data(), sum.data());
            else
              add_rows<2>(shapes, rows, P, weights, sum.data(), sum.data() + P);
            for (std::size_t i = 0; i < n_out * P; ++i)
              out[i] += sum[i];
          }
      }

      template <typename T>
      __attribute__((target("avx2,fma"))) void
      forces_avx2(const T           *shapes,
                  const std::size_t  rows,
                  const std::size_t  P,
                  const T           *loads,
                  const unsigned int n_loads,
                  double            *forces)
      {
        forces_any(shapes, rows, P, loads, n_loads, forces);
      }

      template <typename T>
      __attribute__((target("avx2,fma"))) void
      add_avx2(const T           *shapes,
               const std::size_t  rows,
               const std::size_t  P,
               const double      *weights,
               const unsigned int n_out,
               double            *out)
      {
        add_loop(shapes, rows, P, weights, n_out, out);
      }

      // The block products (block_forces(), add_block_weighted_shapes()):
      // tiles of RT rows (or points) by J columns kept in registers (6 x 16
      // floats or 3 x 16 doubles: 12 of the 16 AVX2 registers), each shape
      // value read once per tile and broadcast, each column vector once per
      // row (or point) of the tile. Measured on one core (Xeon, AVX2 build)
      // at 16 columns in float: 31 G multiply-adds/s for the forces and 28
      // for the sums, of a peak of 37; tiles of 4 rows reached 29 and 23.
      // The AVX-512 copies (tiles twice as tall, below): 38 and 48.
      template <unsigned int J, unsigned int RT, typename T>
      [[gnu::always_inline]] inline void
      block_forces_tile(const T            *s,
                        const std::size_t   P,
                        const unsigned int *points,
                        const std::size_t   n_points,
                        const T            *loads,
                        T                  *forces)
      {
        T acc[RT][J] = {};
        for (std::size_t a = 0; a < n_points; ++a)
          {
            const T          *q = loads + a * J;
            const std::size_t p = points[a];
#pragma GCC unroll 16
            for (unsigned int i = 0; i < RT; ++i)
              {
                const T x = s[i * P + p];
#pragma omp simd
                for (unsigned int j = 0; j < J; ++j)
                  acc[i][j] += x * q[j];
              }
          }
        for (unsigned int i = 0; i < RT; ++i)
#pragma omp simd
          for (unsigned int j = 0; j < J; ++j)
            forces[i * J + j] = acc[i][j];
      }

      template <unsigned int J, unsigned int Wide, typename T>
      [[gnu::always_inline]] inline void
      block_forces_loop(const T            *shapes,
                        const std::size_t   rows,
                        const std::size_t   P,
                        const unsigned int *points,
                        const std::size_t   n_points,
                        const T            *loads,
                        T                  *forces)
      {
        constexpr unsigned int RT = (sizeof(T) == 4 ? 6 : 3) * Wide;
        std::size_t            r  = 0;
        // The pass is the first to read each row, and with a few points
        // loaded it reads them sparsely: the rows three tiles ahead are
        // asked for while this tile is formed (past the last row too: the
        // caller's next rows follow, and a prefetch never faults; the
        // address is formed as an integer, not by pointer arithmetic past
        // the array).
        constexpr std::size_t ahead = 3 * RT;
        const std::uintptr_t  base  = reinterpret_cast<std::uintptr_t>(shapes);
        for (; r + RT <= rows; r += RT)
          {
            if (n_points < P)
              for (std::size_t b = (r + ahead) * P * sizeof(T);
                   b < (r + ahead + RT) * P * sizeof(T); b += 64)
                __builtin_prefetch(reinterpret_cast<const void *>(base + b));
            block_forces_tile<J, RT>(shapes + r * P, P, points, n_points, loads, forces + r * J);
          }
        for (; r < rows; ++r)
          block_forces_tile<J, 1>(shapes + r * P, P, points, n_points, loads, forces + r * J);
      }

      template <unsigned int J, unsigned int PT, typename T>
      [[gnu::always_inline]] inline void
      block_add_tile(const T          *s,
                     const std::size_t rows,
                     const std::size_t P,
                     const T          *weights,
                     double           *out)
      {
        T acc[PT][J] = {};
        for (std::size_t r = 0; r < rows; ++r)
          {
            const T *w = weights + r * J;
#pragma GCC unroll 16
            for (unsigned int i = 0; i < PT; ++i)
              {
                const T x = s[r * P + i];
#pragma omp simd
                for (unsigned int j = 0; j < J; ++j)
                  acc[i][j] += x * w[j];
              }
          }
        for (unsigned int i = 0; i < PT; ++i)
          for (unsigned int j = 0; j < J; ++j)
            out[i * J + j] += acc[i][j];
      }

      template <unsigned int J, unsigned int Wide, typename T>
      [[gnu::always_inline]] inline void
      block_add_loop(const T          *shapes,
                     const std::size_t rows,
                     const std::size_t P,
                     const T          *weights,
                     double           *out)
      {
        constexpr unsigned int PT = (sizeof(T) == 4 ? 6 : 3) * Wide;
        std::size_t            p  = 0;
        for (; p + PT <= P; p += PT)
          block_add_tile<J, PT>(shapes + p, rows, P, weights, out + p * J);
        for (; p < P; ++p)
          block_add_tile<J, 1>(shapes + p, rows, P, weights, out + p * J);
      }

      template <unsigned int Wide, typename T>
      [[gnu::always_inline]] inline void
      block_forces_any(const T            *shapes,
                       const std::size_t   rows,
                       const std::size_t   P,
                       const unsigned int *points,
                       const std::size_t   n_points,
                       const T            *loads,
                       const unsigned int  J,
                       T                  *forces)
      {
        switch (J)
          {
            case 4:
              return block_forces_loop<4, Wide>(shapes, rows, P, points, n_points, loads, forces);
            case 8:
              return block_forces_loop<8, Wide>(shapes, rows, P, points, n_points, loads, forces);
            case 16:
              return block_forces_loop<16, Wide>(shapes, rows, P, points, n_points, loads, forces);
            default:
              throw std::logic_error("block_forces: " + std::to_string(J) +
                                     " columns; allowed: 4, 8 or 16");
          }
      }

      template <unsigned int Wide, typename T>
      [[gnu::always_inline]] inline void
      block_add_any(const T           *shapes,
                    const std::size_t  rows,
                    const std::size_t  P,
                    const T           *weights,
                    const unsigned int J,
                    double            *out)
      {
        switch (J)
          {
            case 4:
              return block_add_loop<4, Wide>(shapes, rows, P, weights, out);
            case 8:
              return block_add_loop<8, Wide>(shapes, rows, P, weights, out);
            case 16:
              return block_add_loop<16, Wide>(shapes, rows, P, weights, out);
            default:
              throw std::logic_error("add_block_weighted_shapes: " + std::to_string(J) +
                                     " columns; allowed: 4, 8 or 16");
          }
      }

      template <typename T>
      __attribute__((target("avx2,fma"))) void
      block_forces_avx2(const T            *shapes,
                        const std::size_t   rows,
                        const std::size_t   P,
                        const unsigned int *points,
                        const std::size_t   n_points,
                        const T            *loads,
                        const unsigned int  J,
                        T                  *forces)
      {
        block_forces_any<1>(shapes, rows, P, points, n_points, loads, J, forces);
      }

      template <typename T>
      __attribute__((target("avx2,fma"))) void
      block_add_avx2(const T           *shapes,
                     const std::size_t  rows,
                     const std::size_t  P,
                     const T           *weights,
                     const unsigned int J,
                     double            *out)
      {
        block_add_any<1>(shapes, rows, P, weights, J, out);
      }

      // With AVX-512 (32 registers of twice the width) the tiles are twice
      // as tall: 12 rows of 16 floats or 6 of 16 doubles, one or two
      // registers a row.
      template <typename T>
      __attribute__((target("avx512f,prefer-vector-width=512"))) void
      block_forces_avx512(const T            *shapes,
                          const std::size_t   rows,
                          const std::size_t   P,
                          const unsigned int *points,
                          const std::size_t   n_points,
                          const T            *loads,
                          const unsigned int  J,
                          T                  *forces)
      {
        block_forces_any<2>(shapes, rows, P, points, n_points, loads, J, forces);
      }

      template <typename T>
      __attribute__((target("avx512f,prefer-vector-width=512"))) void
      block_add_avx512(const T           *shapes,
                       const std::size_t  rows,
                       const std::size_t  P,
                       const T           *weights,
                       const unsigned int J,
                       double            *out)
      {
        block_add_any<2>(shapes, rows, P, weights, J, out);
      }

      bool
      has_avx512()
      {
        static const bool yes = __builtin_cpu_supports("avx512f");
        return yes;
      }

      bool
      has_avx2()
      {
        static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
        return yes;
      }
    } // namespace



    template <typename Shape>
    void
    modal_forces(const Shape       *shapes,
                 const std::size_t  rows,
                 const std::size_t  P,
                 const Shape       *loads,
                 const unsigned int n_loads,
                 double            *forces)
    {
      if (has_avx2())
        forces_avx2(shapes, rows, P, loads, n_loads, forces);
      else
        forces_any(shapes, rows, P, loads, n_loads, forces);
    }



    template <typename Shape>
    void
    add_weighted_shapes(const Shape       *shapes,
                        const std::size_t  rows,
                        const std::size_t  P,
                        const double      *weights,
                        const unsigned int n_out,
                        double            *out)
    {
      if (n_out != 1 && n_out != 2)
        throw std::logic_error("add_weighted_shapes: " + std::to_string(n_out) +
                               " outputs; allowed: 1 or 2");
      if (has_avx2())
        add_avx2(shapes, rows, P, weights, n_out, out);
      else
        add_loop(shapes, rows, P, weights, n_out, out);
    }



    template <typename Shape>
    void
    block_forces(const Shape        *shapes,
                 const std::size_t   rows,
                 const std::size_t   P,
                 const unsigned int *points,
                 const std::size_t   n_points,
                 const Shape        *loads,
                 const unsigned int  J,
                 Shape              *forces)
    {
      if (has_avx512())
        block_forces_avx512(shapes, rows, P, points, n_points, loads, J, forces);
      else if (has_avx2())
        block_forces_avx2(shapes, rows, P, points, n_points, loads, J, forces);
      else
        block_forces_any<1>(shapes, rows, P, points, n_points, loads, J, forces);
    }



    template <typename Shape>
    void
    add_block_weighted_shapes(const Shape       *shapes,
                              const std::size_t  rows,
                              const std::size_t  P,
                              const Shape       *weights,
                              const unsigned int J,
                              double            *out)
    {
      if (has_avx512())
        block_add_avx512(shapes, rows, P, weights, J, out);
      else if (has_avx2())
        block_add_avx2(shapes, rows, P, weights, J, out);
      else
        block_add_any<1>(shapes, rows, P, weights, J, out);
    }



    template void
    block_forces(const double *,
                 std::size_t,
                 std::size_t,
                 const unsigned int *,
                 std::size_t,
                 const double *,
                 unsigned int,
                 double *);
    template void
    block_forces(const float *,
                 std::size_t,
                 std::size_t,
                 const unsigned int *,
                 std::size_t,
                 const float *,
                 unsigned int,
                 float *);
    template void
    add_block_weighted_shapes(const double *,
                              std::size_t,
                              std::size_t,
                              const double *,
                              unsigned int,
                              double *);
    template void
    add_block_weighted_shapes(const float *,
                              std::size_t,
                              std::size_t,
                              const float *,
                              unsigned int,
                              double *);
    template void
    modal_forces(const double *, std::size_t, std::size_t, const double *, unsigned int, double *);
    template void
    modal_forces(const float *, std::size_t, std::size_t, const float *, unsigned int, double *);
    template void
    add_weighted_shapes(const double *,
                        std::size_t,
                        std::size_t,
                        const double *,
                        unsigned int,
                        double *);
    template void
    add_weighted_shapes(const float *,
                        std::size_t,
                        std::size_t,
                        const double *,
                        unsigned int,
                        double *);
  } // namespace convolution
} // namespace greentread
