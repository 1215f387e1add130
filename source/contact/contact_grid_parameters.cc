#include <greentread/base/exceptions.h>
#include <greentread/contact/contact_grid_parameters.h>

#include <string>

namespace greentread
{
  namespace contact
  {
    void
    ContactGridParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Contact grid");
      prm.declare_entry("Subdivisions", "8", dealii::Patterns::Integer(1, 32),
                        "Contact points per Green's-function rectangle along each direction: "
                        "s splits each rectangle ('Green's functions/Patch length' / 'Points "
                        "along' x 'Patch width' / 'Points across') into s x s contact "
                        "rectangles. The finite-element Green's functions carry the "
                        "compliance at the rectangles' scale, an elastic layer (the tread's "
                        "rubber and thickness on a rigid belt) what lies below it. 1: the "
                        "Green's functions' points (the paper's grid). The default 8 (0.75 x "
                        "0.83 mm on the default patch, 7680 points) comes from the "
                        "convergence study benchmarks/contact_grid_study (its README).");
      prm.declare_entry(
        "Solver", "auto",
        dealii::Patterns::Selection("auto|pivoting|projected CG|projected CG on the whole grid"),
        "The contact's complementarity solve at each step: 'auto' is "
        "'projected CG' with a reciprocal patch model ('Patch model/Source' "
        "= fe modes) and 'pivoting' otherwise; 'pivoting' forms "
        "the contact points' N x N compliances and solves by warm-started block "
        "principal pivoting (exact to round-off; 8 N^2 bytes per matrix, up to "
        "10,000 points); 'projected CG' forms no N x N matrix (the tread's "
        "layer by FFT) and solves the bound-constrained quadratic programme by "
        "MPRGP to 'Tolerance' (needs a reciprocal patch "
        "model: 'Patch model/Source' = fe modes), on the candidate points "
        "alone (those the road would be inside, and those in contact at the "
        "last step) with their dense compliances, then checked on the whole "
        "grid, so that a step costs in proportion to the points in contact "
        "(doc/methods/contact.md); 'projected CG on the whole grid': the same "
        "MPRGP on every point, each product by FFT (the reference).");
      prm.declare_entry("Tolerance", "1e-6", dealii::Patterns::Double(1e-14, 1e-3),
                        "Where 'projected CG' stops: when no point's projected gap gradient "
                        "exceeds this fraction of the road's largest demand at the step "
                        "(|u^h - d|_inf), so that a point in contact ends the step inside "
                        "the road by at most that much (the run prints the largest). The "
                        "default 1e-6 (2 to 6 nm on the main job's roads) moves the band "
                        "levels by less than 1e-4 dB from 1e-10 and takes a third fewer "
                        "products (doc/methods/contact.md).");
      prm.leave_subsection();
    }



    void
    ContactGridParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Contact grid");
      subdivisions = prm.get_integer("Subdivisions");
      solver       = prm.get("Solver");
      tolerance    = prm.get_double("Tolerance");
      prm.leave_subsection();
    }



    bool
    ContactGridParameters::matrix_free(const bool reciprocal, const unsigned int n_coarse) const
    {
      const bool projected = solver.rfind("projected CG", 0) == 0;
      if (projected && !reciprocal)
        throw InputError("parameter 'Contact grid/Solver' = " + solver +
                         " needs a reciprocal "
                         "patch model; allowed with 'Patch model/Source' = identified: "
                         "auto or pivoting");
      const bool free = projected || (solver == "auto" && reciprocal);
      // Pivoting holds several N x N matrices (8 N^2 bytes each).
      const std::size_t n = std::size_t(n_coarse) * subdivisions * subdivisions;
      if (!free && n > max_pivoting_points)
        throw InputError("parameter 'Contact grid/Subdivisions' = " + std::to_string(subdivisions) +
                         " gives " + std::to_string(n) +
                         " contact points, too many for the solver 'pivoting' (N x N "
                         "matrices of " +
                         format_printf("%.1f", 8e-9 * double(n) * double(n)) +
                         " GB each); allowed with it: up to " +
                         std::to_string(max_pivoting_points) +
                         " points, or 'Contact grid/Solver' = projected CG with 'Patch "
                         "model/Source' = fe modes");
      return free;
    }
  } // namespace contact
} // namespace greentread
