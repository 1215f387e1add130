#pragma once

// The data rows of a CSV file the program wrote: after its '#' comment lines
// and its header, each row's cells as numbers (an empty cell as NaN).

#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace test
{
  inline std::vector<std::vector<double>>
  read_csv(const std::filesystem::path &file)
  {
    std::ifstream in(file);
    BOOST_TEST_REQUIRE(in.good(), file << " cannot be read");
    std::vector<std::vector<double>> rows;
    std::string                      line;
    bool                             header = true;
    while (std::getline(in, line))
      {
        if (line.empty() || line[0] == '#')
          continue;
        if (header)
          {
            header = false;
            continue;
          }
        // Every cell, the empty ones (a value the program did not estimate)
        // as NaN, a trailing one too.
        std::vector<double> row;
        std::size_t         start = 0;
        while (true)
          {
            const std::size_t comma = line.find(',', start);
            const std::string cell  = line.substr(start, comma - start);
            row.push_back(cell.empty() ? std::numeric_limits<double>::quiet_NaN() :
                                         std::stod(cell));
            if (comma == std::string::npos)
              break;
            start = comma + 1;
          }
        rows.push_back(row);
      }
    return rows;
  }
} // namespace test
