#pragma once

#include <greentread/convolution/patch_convolution.h>
#include <greentread/periodic/contact_patch.h>
#include <greentread/periodic/periodic_cell.h>
#include <greentread/periodic/ring_chain.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/UmfPackSupport>

#include <string>

/**
 * @file
 * The finite-element transient reference: the rolling contact computed with
 * no Green's functions, no modal model and no convolution. Implemented in
 * source/reference/newmark_ring.cc.
 */

namespace greentread
{
  namespace reference
  {
    /**
     * @brief The whole ring, all N cells of @p cell assembled as `full-ring`
     * does (K + Kp, C, M in cylindrical components, the rim seat held),
     * integrated in time by Newmark's average-acceleration rule
     * (\f$\beta = 1/4\f$, \f$\gamma = 1/2\f$: unconditionally stable,
     * second order, no numerical damping), with the ring's own C.
     *
     * It offers the contact the interface of the convolutions, so that the
     * kinematic contact, the road, the static start and the time loop are
     * the same code as the fast path's and only the structure's response
     * differs. With \f$K_{eff} = K + \frac{2}{\Delta t} C + \frac{4}{\Delta
     * t^2} M\f$, one step is
     * \f[ K_{eff} u_{n+1} = r_n + B q_{n+1},\quad
     *     r_n = M\left(\tfrac{4}{\Delta t^2} u_n + \tfrac{4}{\Delta t} v_n + a_n\right)
     *         + C\left(\tfrac{2}{\Delta t} u_n + v_n\right), \f]
     * B the contact points' unit loads (ContactPoint::load). At the points,
     * \f$B^T u_{n+1} = B^T K_{eff}^{-1} r_n + W q_{n+1}\f$: the history term
     * and the condensed effective compliance \f$W = B^T K_{eff}^{-1} B\f$,
     * constant for a constant dt, which is the complementarity problem's
     * matrix (PatchInfluence::u[2]). The force at the step's start acts
     * through \f$a_n\f$, so PatchInfluence::u[1] is zero. K_eff and K are
     * factorised once (UMFPACK); a step is one sparse solve.
     */
    class NewmarkRing : public convolution::PatchConvolution
    {
    public:
      /// @throws NumericalError if K or K_eff cannot be factorised.
      NewmarkRing(const periodic::PeriodicCell &cell,
                  const periodic::ContactPatch &patch,
                  double                        dt);

      /// \f$B^T K_{eff}^{-1} r_n\f$ and the velocity that goes with it.
      void
      history(Eigen::VectorXd &u, Eigen::VectorXd &v) override;

      /// Take the end force of @p load: \f$u_{n+1}\f$, then \f$a_{n+1}\f$, \f$v_{n+1}\f$.
      void
      advance(const convolution::PatchLoad &load) override;

      /// The static state under @p q0: \f$K u = B q_0\f$, at rest.
      void
      preload(const Eigen::VectorXd &q0) override;

      std::string
      name() const override
      {
        return "Newmark, full ring";
      }

      /// \f$B^T K^{-1} B\f$: the ring's static compliance at the points [m/N].
      const Eigen::MatrixXd &
      static_compliance() const
      {
        return static_w;
      }

      /// The ring's unknowns.
      unsigned int
      n_dofs() const
      {
        return ring.size();
      }

    private:
      using SparseLU = Eigen::UmfPackLU<periodic::SparseReal>;

      periodic::RingChain  ring;
      periodic::SparseReal K, C, M, K_eff;
      periodic::SparseReal loads, loads_t; // B and its transpose
      SparseLU             effective, stiffness;
      Eigen::MatrixXd      response; // K_eff^{-1} B
      Eigen::MatrixXd      static_w;
      Eigen::VectorXd      u, v, a, u_free, rhs;
      bool                 have_history = false;
    };
  } // namespace reference
} // namespace greentread
