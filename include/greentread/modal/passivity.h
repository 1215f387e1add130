#pragma once

#include <greentread/modal/patch_model.h>

#include <string>

/**
 * @file
 * The passivity of a patch model, measured where the rolling scene uses it.
 *
 * A passive, reciprocal structure absorbs power at every frequency: the
 * symmetric part of \f$-\mathrm{Im}\,\hat g(\omega)\f$ is positive
 * semidefinite. The measure is the smallest eigenvalue of that matrix over
 * its largest (in absolute value), the worst over the lines: >= 0 for a
 * passive model, to round-off. The ring's own modes give a passive model by
 * construction (a sum of positive semidefinite terms, when the shapes are
 * real); the identified model (LSCE poles and fitted residues, Appendix A)
 * need not be, and a model that is not passive can put energy into the
 * rolling contact that the tyre would not. Implemented in
 * source/modal/passivity.cc.
 */

namespace greentread
{
  namespace modal
  {
    /// The passivity measure of a model over a set of lines.
    struct Passivity
    {
      /// The smallest eigenvalue of -Im g over its largest, the worst line.
      double worst = 1.;
      /// The frequency of that line [Hz].
      double frequency = 0.;
      /// The number of lines measured.
      unsigned int lines = 0;
    };

    /// Below this, a model is not passive (round-off of a passive one:
    /// 1e-12 and smaller, measured on the ring's modes).
    constexpr double passivity_tolerance = 1e-9;

    /**
     * @brief The passivity of @p model on the lines l df, l = 1..n_lines
     * (the Green's functions' lines above 0 Hz).
     */
    Passivity
    measure_passivity(const PatchModel &model, double df, unsigned int n_lines);

    /// Print the measure on standard output, naming @p what.
    void
    print_passivity(const Passivity &passivity, const std::string &what);

    /**
     * @brief Act on the measure: a passive model passes; a
     * model that is not passive is refused with an InputError that names
     * the figure and `Patch model/Allow non-passive`, or, when @p allow is
     * set, rolled with a warning on standard error that names the figure.
     * @p what names the model ("the identified patch model").
     */
    void
    check_passivity(const Passivity &passivity, bool allow, const std::string &what);
  } // namespace modal
} // namespace greentread
