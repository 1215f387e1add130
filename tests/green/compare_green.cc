// compare_green A.h5 B.h5 TOLERANCE
//
// Prints the largest |g_A - g_B| / max |g_A| over all frequencies and
// pairs, and exits 1 if it exceeds TOLERANCE or the grids or points differ.
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
      if (a.n_lines != b.n_lines || a.df != b.df || a.points != b.points)
        {
          std::cerr << "the frequency grids or the points differ\n";
          return 1;
        }
      double largest = 0., difference = 0.;
      for (std::size_t e = 0; e < a.values.size(); ++e)
        {
          if (!std::isfinite(std::abs(a.values[e])) || !std::isfinite(std::abs(b.values[e])))
            {
              std::cerr << "value " << e << " is not finite\n";
              return 1;
            }
          largest    = std::max(largest, std::abs(a.values[e]));
          difference = std::max(difference, std::abs(a.values[e] - b.values[e]));
        }
      std::cout << "largest relative difference " << difference / largest << " over "
                << a.values.size() << " values\n";
      return difference <= tolerance * largest ? 0 : 1;
    }
  catch (const std::exception &e)
    {
      std::cerr << "compare_green: " << e.what() << '\n';
      return 2;
    }
}
