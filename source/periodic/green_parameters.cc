#include <greentread/base/exceptions.h>
#include <greentread/base/frequency_response.h>
#include <greentread/base/parameters.h>
#include <greentread/periodic/green_parameters.h>

#include <cmath>
#include <string>

namespace greentread
{
  namespace periodic
  {
    using base::RangePattern;

    void
    GreenParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Green's functions");
      {
        prm.declare_entry("Maximum frequency", "4000", base::RangePattern::positive("Hz"),
                          "f_max, the last line of the grid. Unit: Hz. Paper, Section 5.1: "
                          "4000 Hz.");
        prm.declare_entry("Frequency step", "500", base::RangePattern::positive("Hz"),
                          "df, the line spacing: the grid is 0, df, ..., f_max, and f_max / df "
                          "must be a whole number. With 'Patch model/Source' = fe modes (the "
                          "default) the lines only check the modal synthesis (E of Eq. 50): "
                          "the default 500 Hz gives 9. With 'identified' the LSCE fit needs "
                          "long impulse responses (1 / df): use 15.625 Hz = 4000 / 256 (64 ms, "
                          "as prm/tyre_green.prm). Unit: Hz.");
        prm.declare_entry("Method", "harmonic",
                          dealii::Patterns::Selection("bloch|doubling|full-ring|harmonic"),
                          "'harmonic': the section's circumferential harmonics, for an "
                          "axisymmetric ring (no mesh along the ring; 'Number of cells' "
                          "then only places the points; the default). "
                          "'bloch': a discrete Fourier transform over the N identical cells, "
                          "N/2 + 1 sparse cell solves per frequency (exact). "
                          "'doubling': the paper's recursive doubling of the condensed cell "
                          "(Eqs. 46-49; exact, dense). 'full-ring': all N cells in one sparse "
                          "solve (the reference; coarse meshes only).");
        prm.declare_entry("Harmonic tolerance", "1e-3", base::RangePattern::closed(1e-8, 0.1, ""),
                          "'Method' = harmonic: the harmonics 0 .. N - 1 are summed, N the "
                          "first for which a bound of the neglected static tail is below "
                          "this fraction of the smallest static driving point "
                          "(doc/methods/green-functions.md). Unit: 1.");
        prm.declare_entry("Patch length", "0.06", base::RangePattern::positive("m"),
                          "L_c, the contact patch along the rolling direction x. Unit: m. "
                          "Section 5.2: 6 cm.");
        prm.declare_entry("Patch width", "0.08", base::RangePattern::positive("m"),
                          "l_c, the contact patch across the tread (y). Unit: m. Section 5.2: "
                          "8 cm.");
        prm.declare_entry("Points along", "10", dealii::Patterns::Integer(1, 1000),
                          "N_x, contact points along x. Section 5.2: 10.");
        prm.declare_entry("Points across", "12", dealii::Patterns::Integer(1, 1000),
                          "N_y, contact points across y. Section 5.2: 12.");
        prm.declare_entry(
          "Point load", "tributary area", dealii::Patterns::Selection("node|tributary area"),
          "What a unit force at a contact point is. 'node': a radial force on one tread "
          "node, the points on a whole stride of nodes nearest the spacing asked (the "
          "paper's; singular in 3D elasticity, so the driving point grows as the mesh is "
          "refined). 'tributary area': a uniform radial traction 1 / A over the point's "
          "rectangle L_c / N_x x l_c / N_y, the response the mean radial displacement over "
          "it; the points exactly on the grid asked, on any mesh (the default).");
        prm.declare_entry("Pairs", "auto", dealii::Patterns::Anything(),
                          "The g_ij written as green_<i>_<j>.csv and plotted: 'auto' (the "
                          "driving point p = (N_x/2) N_y + N_y/2 nearest the patch centre, and "
                          "its transfers to the previous point along x and across y), or up "
                          "to 12 pairs 'i:j, i:j, ...' (0-based points, p = i_x N_y + i_y).");
        prm.declare_entry("Deflection shape frequency", "500", dealii::Patterns::Double(-1.),
                          "The frequency of the operating deflection shape of the ring "
                          "(ring_deflection.vtu) under a unit radial force at point j of the "
                          "first pair (with 'auto', the driving point); a negative value "
                          "writes none. Unit: Hz.");
      }
      prm.leave_subsection();
    }



    std::optional<HarmonicOptions>
    GreenParameters::harmonic() const
    {
      if (method != "harmonic")
        return std::nullopt;
      return HarmonicOptions{harmonic_tolerance, 2. * M_PI * max_frequency};
    }



    void
    GreenParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Green's functions");
      {
        max_frequency       = prm.get_double("Maximum frequency");
        frequency_step      = prm.get_double("Frequency step");
        method              = prm.get("Method");
        harmonic_tolerance  = prm.get_double("Harmonic tolerance");
        patch.length        = prm.get_double("Patch length");
        patch.width         = prm.get_double("Patch width");
        patch.points_along  = prm.get_integer("Points along");
        patch.points_across = prm.get_integer("Points across");
        patch.load = prm.get("Point load") == "node" ? PointLoad::node : PointLoad::tributary_area;
        pairs      = prm.get("Pairs");
        deflection_frequency = prm.get_double("Deflection shape frequency");
      }
      prm.leave_subsection();
      if (method == "harmonic" && patch.load == PointLoad::node)
        throw InputError("parameter 'Green's functions/Point load' = node is not allowed with "
                         "'Method' = harmonic: a point force's harmonic series does not "
                         "converge (its displacement is singular); allowed: tributary area");
      require_parameter(frequency_step <= max_frequency, "Green's functions/Frequency step",
                        frequency_step,
                        "at most 'Maximum frequency' = " + format_number(max_frequency) + " Hz");
      const double lines = max_frequency / frequency_step;
      require_parameter(
        std::abs(lines - std::round(lines)) < 1e-9 * lines, "Green's functions/Frequency step",
        frequency_step,
        "a whole fraction of 'Maximum frequency' = " + format_number(max_frequency) +
          " Hz (f_max / df = " + format_short(lines) + ")");
      require_parameter(lines <= 1e6, "Green's functions/Frequency step", frequency_step,
                        "at least f_max / 1e6");
      require_parameter(deflection_frequency <= max_frequency,
                        "Green's functions/Deflection shape frequency", deflection_frequency,
                        "at most 'Maximum frequency' = " + format_number(max_frequency) +
                          " Hz, or negative for none");
    }



    unsigned int
    GreenParameters::n_lines() const
    {
      return static_cast<unsigned int>(std::lround(max_frequency / frequency_step)) + 1;
    }



    std::vector<std::pair<unsigned int, unsigned int>>
    GreenParameters::csv_pairs(const ContactPatch &contact) const
    {
      const unsigned int n = contact.points.size();
      if (pairs != "auto")
        {
          // Each pair is a CSV file and a curve in one plot: a few, not all.
          const auto chosen = base::parse_point_pairs(pairs, n, "Green's functions/Pairs");
          require_parameter(chosen.size() <= 12, "Green's functions/Pairs", pairs,
                            "'auto' or at most 12 pairs i:j (this names " +
                              std::to_string(chosen.size()) +
                              "); the whole matrix is in green_functions.h5");
          return chosen;
        }
      const unsigned int nx = contact.points_along, ny = contact.points_across;
      const unsigned int centre                                 = (nx / 2) * ny + ny / 2;
      std::vector<std::pair<unsigned int, unsigned int>> result = {{centre, centre}};
      if (nx > 1)
        result.emplace_back(centre, centre - ny);
      if (ny > 1)
        result.emplace_back(centre, centre - 1);
      return result;
    }
  } // namespace periodic
} // namespace greentread
