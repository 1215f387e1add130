#include <greentread/analysis/error_bar_parameters.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>

#include <algorithm>

namespace greentread
{
  namespace analysis
  {
    std::string
    label(const Discretisation d)
    {
      switch (d)
        {
          case Discretisation::time_step:
            return "time_step";
          case Discretisation::contact_grid:
            return "contact_grid";
          case Discretisation::mode_cutoff:
            return "mode_cutoff";
          case Discretisation::ring_section:
            return "ring_section";
          case Discretisation::block_mesh:
            return "block_mesh";
        }
      return "";
    }



    std::string
    describe(const Discretisation d)
    {
      std::string s = label(d);
      std::replace(s.begin(), s.end(), '_', ' ');
      return s;
    }



    bool
    ErrorBarParameters::estimates_any(const Discretisation d) const
    {
      return std::find(estimates.begin(), estimates.end(), d) != estimates.end();
    }



    void
    ErrorBarParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Error bars");
      {
        prm.declare_entry(
          "Estimates", "time step, contact grid, mode cutoff, ring section, block mesh",
          dealii::Patterns::MultipleSelection(
            "time step|contact grid|mode cutoff|ring section|block mesh"),
          "The discretisations whose error each band level gets an estimate of, each from one "
          "other level on the saved stages: 'time step' (the scene's step halved; the "
          "low-rate run's bands against the run at the scene's step, no extra run; the run at "
          "the scene's step also gets its rolling resistance's error bar from it), 'contact "
          "grid' ('Contact grid/Subdivisions' halved), 'mode cutoff' (the modes up to 'Coarser "
          "mode cutoff' times 'Patch model/Mode cutoff'), 'ring section' ('Geometry/Mesh size' "
          "doubled: its own Green's functions and modes, saved in coarser_section/), 'block "
          "mesh' (with finite tread blocks, 'Tread pattern/Block mesh size' times 3/2; the "
          "patterned runs only). The "
          "estimate is the level difference scaled by the order (doc/methods/analysis.md); "
          "spectra.csv gives each, and their combination with the standard error. Empty: no "
          "estimate, no extra run.");
        prm.declare_entry(
          "Lines in the lowest band", "4", dealii::Patterns::Integer(1, 1000),
          "The error bars' runs roll only as long as gives the lowest band they estimate this many "
          "Fourier lines (from 'Spectra/Target from' up): the estimate is a difference on the "
          "same road and start, whose scatter is far below each level's. More: a longer, "
          "steadier estimate.");
        prm.declare_entry(
          "Coarser mode cutoff", "0.75", base::RangePattern::closed(0.3, 0.95, ""),
          "The mode cutoff estimate's coarser level: the ring's modes up to this fraction of "
          "'Patch model/Mode cutoff', with their own static residual.");
      }
      prm.leave_subsection();
    }



    void
    ErrorBarParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Error bars");
      {
        const auto chosen = dealii::Utilities::split_string_list(prm.get("Estimates"));
        estimates.clear();
        for (const Discretisation d : all_discretisations)
          if (std::find(chosen.begin(), chosen.end(), describe(d)) != chosen.end())
            estimates.push_back(d);
        window_lines = prm.get_integer("Lines in the lowest band");
        cutoff_ratio = prm.get_double("Coarser mode cutoff");
      }
      prm.leave_subsection();
    }
  } // namespace analysis
} // namespace greentread
