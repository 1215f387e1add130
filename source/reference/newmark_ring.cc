#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/serial_blas.h>
#include <greentread/reference/newmark_ring.h>

#include <cmath>

namespace greentread
{
  namespace reference
  {
    namespace
    {
      /// Factorise @p A, or say which matrix could not be.
      void
      factorise(Eigen::UmfPackLU<periodic::SparseReal> &lu,
                const periodic::SparseReal             &A,
                const std::string                      &what)
      {
        // No iterative refinement: the set-up's solves are checked against
        // the backward-error bound instead, and refinement tripled a step's cost.
        lu.umfpackControl()(UMFPACK_IRSTEP) = 0;
        const auto lock                     = base::lock_serial_blas();
        lu.compute(A);
        if (lu.info() != Eigen::Success)
          throw NumericalError("Newmark reference: UMFPACK could not factorise " + what +
                               " of the "
                               "full ring (" +
                               std::to_string(A.rows()) +
                               " unknowns, UMFPACK "
                               "status " +
                               std::to_string(lu.umfpackFactorizeReturncode()) + ")");
      }

      /// Solve A X = B and check the normwise backward error, as the
      /// Green's solvers do.
      Eigen::MatrixXd
      checked_solve(const Eigen::UmfPackLU<periodic::SparseReal> &lu,
                    const periodic::SparseReal                   &A,
                    const Eigen::MatrixXd                        &B,
                    const std::string                            &what)
      {
        Eigen::MatrixXd X;
        {
          const auto lock = base::lock_serial_blas();
          X               = lu.solve(B);
        }
        double norm_a = 0.;
        for (int c = 0; c < A.outerSize(); ++c)
          norm_a = std::max(norm_a, A.col(c).cwiseAbs().sum());
        for (Eigen::Index j = 0; j < B.cols(); ++j)
          {
            const double error = (A * X.col(j) - B.col(j)).lpNorm<1>() /
                                 (norm_a * X.col(j).lpNorm<1>() + B.col(j).lpNorm<1>());
            if (!(error < 1e-10))
              throw NumericalError("Newmark reference: the solve with " + what +
                                   " of the full ring has a backward error of " +
                                   format_short(error) + " (allowed: 1e-10)");
          }
        return X;
      }
    } // namespace



    NewmarkRing::NewmarkRing(const periodic::PeriodicCell &cell,
                             const periodic::ContactPatch &patch,
                             const double                  dt_)
        : convolution::PatchConvolution(patch.points.size(), dt_)
        , ring{cell.n_face, cell.n_interior, cell.n_cells, cell.n_cells}
    {
      if (!(dt > 0.) || !std::isfinite(dt))
        throw NumericalError("Newmark reference: the time step " + format_short(dt) +
                             " s is not allowed; allowed: a finite time step > 0");
      K                       = ring.assemble(cell.stiffness);
      C                       = ring.assemble(cell.damping);
      M                       = ring.assemble(cell.mass);
      const Eigen::MatrixXd B = ring.loads(patch);
      loads                   = B.sparseView();
      loads_t                 = loads.transpose();

      // Eigen's UmfPackLU keeps a reference to the matrix and hands it to
      // every solve: it lives as long as its factorisation.
      K_eff = K + (2. / dt) * C + (4. / (dt * dt)) * M;
      factorise(effective, K_eff, "the effective stiffness K + 2C/dt + 4M/dt^2");
      factorise(stiffness, K, "the stiffness K + Kp");
      response = checked_solve(effective, K_eff, B, "the effective stiffness");
      static_w = B.transpose() * checked_solve(stiffness, K, B, "the stiffness");

      const unsigned int n = n_p;
      for (unsigned int g = 0; g < 4; ++g)
        {
          psi.u[g] = Eigen::MatrixXd::Zero(n, n);
          psi.v[g] = Eigen::MatrixXd::Zero(n, n);
        }
      psi.u[2]          = B.transpose() * response;
      psi.u[2]          = 0.5 * (psi.u[2] + psi.u[2].transpose()).eval();
      psi.v[2]          = (2. / dt) * psi.u[2];
      psi.instantaneous = true;

      u = v = a = Eigen::VectorXd::Zero(ring.size());
    }



    void
    NewmarkRing::history(Eigen::VectorXd &uh, Eigen::VectorXd &vh)
    {
      rhs = M * ((4. / (dt * dt)) * u + (4. / dt) * v + a) + C * ((2. / dt) * u + v);
      {
        const auto lock = base::lock_serial_blas();
        u_free          = effective.solve(rhs);
      }
      have_history = true;
      uh           = loads_t * u_free;
      // v_{n+1} = 2 (u_{n+1} - u_n) / dt - v_n with no force at the end.
      vh = loads_t * ((2. / dt) * (u_free - u) - v);
    }



    void
    NewmarkRing::advance(const convolution::PatchLoad &load)
    {
      if (!have_history)
        {
          Eigen::VectorXd uh, vh;
          history(uh, vh);
        }
      const Eigen::VectorXd u_next = u_free + response * load.component[2];
      const Eigen::VectorXd a_next = (4. / (dt * dt)) * (u_next - u) - (4. / dt) * v - a;
      v += 0.5 * dt * (a + a_next);
      a            = a_next;
      u            = u_next;
      have_history = false;
      if (!u.allFinite())
        throw NumericalError("Newmark reference: the displacement of the ring is not finite "
                             "(largest contact force " +
                             format_short(load.component[2].cwiseAbs().maxCoeff()) + " N)");
    }



    void
    NewmarkRing::preload(const Eigen::VectorXd &q0)
    {
      const Eigen::VectorXd load = loads * q0;
      const auto            lock = base::lock_serial_blas();
      u                          = stiffness.solve(load);
      v.setZero();
      a.setZero();
      have_history = false;
    }
  } // namespace reference
} // namespace greentread
