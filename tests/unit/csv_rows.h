#pragma once

// The data rows of a CSV file the program wrote: after its '#' comment lines
// and its header, each row's cells as numbers.

#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
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
        std::vector<double> row;
        std::stringstream   ss(line);
        std::string         cell;
        while (std::getline(ss, cell, ','))
          row.push_back(std::stod(cell));
        rows.push_back(row);
      }
    return rows;
  }
} // namespace test
