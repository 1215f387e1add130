// compare_green A.h5 B.h5 TOLERANCE
//
// Prints the largest |g_A - g_B| / max |g_A| over the lines both grids have
// and every pair, and exits 1 if it exceeds TOLERANCE, if the points differ
// or if the grids share no line (one step must be a whole multiple of the
// other).
#include <greentread/base/exceptions.h>
#include <greentread/base/frequency_response.h>

#include <cmath>
#include <iostream>
#include <string>

int
main(int argc, char **argv)
{
  if (argc != 4)
    {
      std::cerr << "usage: compare_green A.h5 B.h5 TOLERANCE\n";
      return 2;
    }
  try
    {
      const auto   a         = greentread::base::read_green_hdf5(argv[1]);
      const auto   b         = greentread::base::read_green_hdf5(argv[2]);
      const double tolerance = std::stod(argv[3]);
      if (a.points != b.points)
        {
          std::cerr << "the points differ\n";
          return 1;
        }
      // The shared lines: every line of the sparser grid that the other has.
      const double       df     = std::max(a.df, b.df);
      const double       ratio  = df / std::min(a.df, b.df);
      const unsigned int step   = static_cast<unsigned int>(std::lround(ratio));
      const unsigned int step_a = a.df < b.df ? step : 1, step_b = b.df < a.df ? step : 1;
      if (std::abs(ratio - step) > 1e-9)
        {
          std::cerr << "the frequency grids share no lines (df " << a.df << " and " << b.df
                    << " Hz)\n";
          return 1;
        }
      const std::size_t P = a.n_points(), pairs = P * P;
      double            largest = 0., difference = 0.;
      unsigned int      lines = 0;
      for (unsigned int l = 0; l * step_a < a.n_lines && l * step_b < b.n_lines; ++l, ++lines)
        for (std::size_t e = 0; e < pairs; ++e)
          {
            const auto ga = a.values[l * step_a * pairs + e], gb = b.values[l * step_b * pairs + e];
            if (!std::isfinite(std::abs(ga)) || !std::isfinite(std::abs(gb)))
              {
                std::cerr << "a value at " << l * df << " Hz is not finite\n";
                return 1;
              }
            largest    = std::max(largest, std::abs(ga));
            difference = std::max(difference, std::abs(ga - gb));
          }
      std::cout << "largest relative difference " << difference / largest << " over " << lines
                << " lines every " << df << " Hz, " << pairs << " pairs each\n";
      return difference <= tolerance * largest ? 0 : 1;
    }
  catch (const std::exception &e)
    {
      std::cerr << "compare_green: " << e.what() << '\n';
      return 2;
    }
}
