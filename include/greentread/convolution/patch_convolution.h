#pragma once

#include <greentread/convolution/convolution.h>
#include <greentread/modal/patch_model.h>

#include <Eigen/Core>

#include <array>
#include <functional>
#include <memory>
#include <vector>

/**
 * @file
 * The convolution of every g_ij of a patch with the point loads, step by step
 * (Section 5): the exact modal recursion and the direct sum, its reference.
 * Conventions as in greentread/contact/patch_contact.h. Implemented in
 * source/convolution/patch_convolution.cc.
 */

namespace greentread
{
  namespace convolution
  {
    /// The loads of one step at every point, components as in StepLoad.
    struct PatchLoad
    {
      std::array<Eigen::VectorXd, 4> component; // impulse_start, start, end, impulse_end

      explicit PatchLoad(unsigned int n = 0)
      {
        for (auto &c : component)
          c = Eigen::VectorXd::Zero(n);
      }

      /// The impulse of the step at every point [N s].
      Eigen::VectorXd
      impulse(double dt) const
      {
        return component[0] + component[3] + 0.5 * dt * (component[1] + component[2]);
      }
    };

    /**
     * @brief The response at \f$t_{n+1}\f$ (rows) to a unit value of one load
     * component at one point (columns): \f$\Psi\f$ of Eq. (20) for the patch.
     */
    struct PatchInfluence
    {
      std::array<Eigen::MatrixXd, 4> u, v;
      /// Whether the model has an instantaneous compliance G_r: then an
      /// impulse would move a point infinitely far, the impulse columns are
      /// not to be used, and the contact force is continuous in time.
      bool instantaneous = false;
      /// The matrix-free form (u and v then empty; only with an
      /// instantaneous compliance): y += \f$\Psi^u_g\f$ x.
      std::function<void(unsigned int g, const Eigen::VectorXd &x, Eigen::VectorXd &y)> add_u;
      /// With add_u, optionally: out = \f$\Psi^u_{end}\f$'s block on two
      /// sets of points (rows and columns), for the contact's candidate-set
      /// solve (greentread/contact/candidate_set.h); empty: the solve works
      /// on the whole grid.
      std::function<void(const std::vector<unsigned int> &rows,
                         const std::vector<unsigned int> &columns,
                         Eigen::MatrixXd                 &out)>
        block_u;
      /// With add_u: the matrix-free solve's tolerance, the projected
      /// gradient it ends at relative to the road's largest demand
      /// (greentread/contact/projected_cg.h).
      double tolerance = 1e-10;
      /// With add_u: a bound on \f$\|\Psi^u_{end}\|_2\f$ over the whole
      /// run, when that compliance changes from step to step (a tread
      /// pattern's finite blocks, contact/tread_block.h); 0: it does not,
      /// and the solve measures its norm once.
      double end_norm = 0.;
    };

    /// y += \f$\Psi^u_g\f$ x, from the matrix's columns where x is not zero
    /// (the loads of the points in contact) or by the matrix-free form.
    void
    add_influence(const PatchInfluence  &psi,
                  unsigned int           g,
                  const Eigen::VectorXd &x,
                  Eigen::VectorXd       &y);

    /**
     * @brief Step-by-step convolution of a patch's Green's functions; the
     * multi-point analogue of convolution::Convolution.
     */
    class PatchConvolution
    {
    public:
      PatchConvolution(unsigned int n_points, double dt)
          : n_p(n_points)
          , dt(dt)
      {
      }

      virtual ~PatchConvolution() = default;

      /// The history term \f$u^h, v^h\f$ at \f$t_{n+1}\f$ at every point.
      virtual void
      history(Eigen::VectorXd &u, Eigen::VectorXd &v) = 0;

      /// The history's displacement alone: all a contact with a continuous
      /// force needs (influence().instantaneous). A convolution may then
      /// leave the velocity out of its later steps; history() still gives it.
      virtual void
      history_u(Eigen::VectorXd &u)
      {
        Eigen::VectorXd v(n_p);
        history(u, v);
      }

      /// Record the loads of the current step and move to the next.
      virtual void
      advance(const PatchLoad &load) = 0;

      /// Start from a constant load @p q0 applied since \f$t = -\infty\f$.
      virtual void
      preload(const Eigen::VectorXd &q0) = 0;

      const PatchInfluence &
      influence() const
      {
        return psi;
      }

      unsigned int
      n_points() const
      {
        return n_p;
      }

      double
      time_step() const
      {
        return dt;
      }

      virtual std::string
      name() const = 0;

    protected:
      unsigned int   n_p;
      double         dt;
      PatchInfluence psi;
    };

    /**
     * @brief The precision in which the rank-one update (a model of the
     * ring's own modes) keeps the mode shapes: the update reads every shape
     * once per step and is limited by memory bandwidth, so single precision
     * (each value rounded to 6e-8 of itself) halves its bytes. The states,
     * the loads and the history stay in double precision; with single
     * precision the products run in float (greentread/contact/
     * shape_kernels.h).
     */
    enum class ShapePrecision
    {
      double_precision,
      single_precision
    };

    /**
     * @brief The exact modal recursion of greentread/convolution/
     * modal_recursive_convolution.h for every pair at once: one complex state
     * per (pole, loaded point), \f$N_m N_p\f$ of them, and the history
     * \f$u_i = \mathrm{Re}\sum_{k,j} c_{kij}\,e^{\lambda_k\Delta t} s_{kj}\f$ as
     * one dense matrix-vector product of size \f$2N_p \times 2N_mN_p\f$ per
     * step, split over @p n_threads threads by rows.
     */
    std::unique_ptr<PatchConvolution>
    make_modal_patch_convolution(const modal::PatchModel &model,
                                 double                   dt,
                                 unsigned int             n_threads = 1,
                                 ShapePrecision precision = ShapePrecision::double_precision);

    /**
     * @brief The reference: the convolution sum of Eq. (39)-(40) over every
     * past step, with the kernel of each pair evaluated at every lag from
     * the same modal model (so the difference to the recursion is the
     * recursion's own error, not the fit's). Memory \f$8 N_p^2 N_g\f$ doubles:
     * keep @p n_kernel (the kernel length in steps) for short runs.
     * The preload's tail is the free decay of the model.
     */
    std::unique_ptr<PatchConvolution>
    make_direct_patch_convolution(const modal::PatchModel &model, double dt, unsigned int n_kernel);
  } // namespace convolution
} // namespace greentread
