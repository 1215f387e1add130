#include <greentread/base/exceptions.h>
#include <greentread/contact/patch_contact.h>
#include <greentread/convolution/exponential_integrals.h>

#include <deal.II/base/thread_management.h>

#include <cmath>
#include <utility>

namespace greentread
{
  namespace contact
  {
    namespace
    {
      /// Per-pole quantities shared by both convolutions.
      struct PoleWeights
      {
        // Per term k: e^{lambda dt} and the weights of the start and end
        // values of a linear load (greentread/convolution/
        // modal_recursive_convolution.h).
        std::vector<std::complex<double>> alpha, beta_a, beta_b;
        // Per term k: c_u = s R, c_v = s R lambda, s = 2 for pairs, 1 for real poles.
        std::vector<Eigen::MatrixXcd> cu, cv;
        // The instantaneous compliance (may be empty) and the step.
        Eigen::MatrixXd instantaneous;
        double          dt;

        PoleWeights(const modal::PatchModel &model, const double dt_)
          : instantaneous(model.instantaneous)
          , dt(dt_)
        {
          if (!(dt > 0.) || !std::isfinite(dt))
            throw InputError("patch convolution: time step " + format_short(dt) +
                             " s is not allowed; allowed: a finite number > 0");
          for (unsigned int k = 0; k < model.n_terms(); ++k)
            {
              const std::complex<double> l = model.lambda[k];
              if (!(l.real() < 0.))
                throw NumericalError("patch convolution: pole " + std::to_string(k) +
                                     " has Re(lambda) = " + format_short(l.real()) +
                                     " >= 0; only stable poles can be convolved");
              const auto psi = convolution::exponential_moments(l * dt);
              alpha.push_back(std::exp(l * dt));
              beta_a.push_back(dt * psi[1]);
              beta_b.push_back(dt * (psi[0] - psi[1]));
              const double scale = model.real[k] ? 1. : 2.;
              Eigen::MatrixXcd r = scale * model.residues[k];
              if (model.real[k])
                r = r.real().cast<std::complex<double>>();
              cu.push_back(r);
              cv.push_back(r * l);
            }
        }

        /// Re sum_k c_k z_k for per-term coefficients z.
        static Eigen::MatrixXd
        contract(const std::vector<Eigen::MatrixXcd>        &c,
                 const std::vector<std::complex<double>> &z)
        {
          Eigen::MatrixXd result = Eigen::MatrixXd::Zero(c[0].rows(), c[0].cols());
          for (std::size_t k = 0; k < c.size(); ++k)
            result += (c[k].real() * z[k].real() - c[k].imag() * z[k].imag());
          return result;
        }

        PatchInfluence
        influence() const
        {
          const std::vector<std::complex<double>> ones(alpha.size(), 1.);
          PatchInfluence                          psi;
          const Eigen::MatrixXd                   g0 = contract(cu, ones);
          psi.u = {{contract(cu, alpha), contract(cu, beta_a), contract(cu, beta_b), g0}};
          psi.v = {{contract(cv, alpha), contract(cv, beta_a), contract(cv, beta_b) + g0,
                    contract(cv, ones)}};
          if (instantaneous.size() && instantaneous.cwiseAbs().maxCoeff() > 0.)
            {
              // u = G_r q(t): the end value acts at once; the slope of the
              // linear load, (end - start) / dt, gives G_r q'.
              psi.u[2] += instantaneous;
              psi.v[1] -= instantaneous / dt;
              psi.v[2] += instantaneous / dt;
              psi.instantaneous = true;
            }
          return psi;
        }
      };



      class ModalPatchConvolution : public PatchConvolution
      {
      public:
        ModalPatchConvolution(const modal::PatchModel &model, const double dt,
                              const unsigned int n_threads)
          : PatchConvolution(model.n_points(), dt)
          , n_terms(model.n_terms())
          , threads(n_threads)
        {
          const PoleWeights w(model, dt);
          psi                   = w.influence();
          const Eigen::Index nk = Eigen::Index(n_terms) * n_p;
          Au.resize(n_p, 2 * nk);
          Av.resize(n_p, 2 * nk);
          for (unsigned int k = 0; k < n_terms; ++k)
            {
              Au.middleCols(Eigen::Index(k) * n_p, n_p)      = w.cu[k].real();
              Au.middleCols(nk + Eigen::Index(k) * n_p, n_p) = -w.cu[k].imag();
              Av.middleCols(Eigen::Index(k) * n_p, n_p)      = w.cv[k].real();
              Av.middleCols(nk + Eigen::Index(k) * n_p, n_p) = -w.cv[k].imag();
            }
          lambda.resize(n_terms);
          alpha.resize(n_terms);
          beta_a.resize(n_terms);
          beta_b.resize(n_terms);
          for (unsigned int k = 0; k < n_terms; ++k)
            {
              lambda[k] = model.lambda[k];
              alpha[k]  = w.alpha[k];
              beta_a[k] = w.beta_a[k];
              beta_b[k] = w.beta_b[k];
            }
          state = Eigen::VectorXd::Zero(2 * nk);
          hist  = Eigen::VectorXd::Zero(2 * nk);
        }

        void
        history(Eigen::VectorXd &u, Eigen::VectorXd &v) override
        {
          const Eigen::Index nk = Eigen::Index(n_terms) * n_p;
          for (unsigned int k = 0; k < n_terms; ++k)
            {
              const double ar = alpha[k].real(), ai = alpha[k].imag();
              auto         sr = state.segment(Eigen::Index(k) * n_p, n_p);
              auto         si = state.segment(nk + Eigen::Index(k) * n_p, n_p);
              hist.segment(Eigen::Index(k) * n_p, n_p)      = ar * sr - ai * si;
              hist.segment(nk + Eigen::Index(k) * n_p, n_p) = ar * si + ai * sr;
            }
          if (threads > 1)
            {
              auto task = dealii::Threads::new_task([&]() { u.noalias() = Au * hist; });
              v.noalias() = Av * hist;
              task.join();
            }
          else
            {
              u.noalias() = Au * hist;
              v.noalias() = Av * hist;
            }
          history_ready = true;
        }

        void
        advance(const PatchLoad &load) override
        {
          if (!history_ready)
            {
              Eigen::VectorXd u(n_p), v(n_p);
              history(u, v);
            }
          const Eigen::Index nk = Eigen::Index(n_terms) * n_p;
          const auto &p = load.component[0], &a = load.component[1], &b = load.component[2],
                     &e = load.component[3];
          for (unsigned int k = 0; k < n_terms; ++k)
            {
              state.segment(Eigen::Index(k) * n_p, n_p) =
                hist.segment(Eigen::Index(k) * n_p, n_p) + beta_a[k].real() * a +
                beta_b[k].real() * b + alpha[k].real() * p + e;
              state.segment(nk + Eigen::Index(k) * n_p, n_p) =
                hist.segment(nk + Eigen::Index(k) * n_p, n_p) + beta_a[k].imag() * a +
                beta_b[k].imag() * b + alpha[k].imag() * p;
            }
          history_ready = false;
        }

        void
        preload(const Eigen::VectorXd &q0) override
        {
          // s_k = int_{-inf}^0 e^{-lambda tau} q0 dtau = -q0 / lambda_k.
          const Eigen::Index nk = Eigen::Index(n_terms) * n_p;
          for (unsigned int k = 0; k < n_terms; ++k)
            {
              const std::complex<double> f = -1. / lambda[k];
              state.segment(Eigen::Index(k) * n_p, n_p)      = f.real() * q0;
              state.segment(nk + Eigen::Index(k) * n_p, n_p) = f.imag() * q0;
            }
          history_ready = false;
        }

        std::string
        name() const override
        {
          return "modal-recursive";
        }

      private:
        unsigned int                      n_terms;
        unsigned int                      threads;
        Eigen::MatrixXd                   Au, Av;
        std::vector<std::complex<double>> lambda, alpha, beta_a, beta_b;
        Eigen::VectorXd                   state, hist;
        bool                              history_ready = false;
      };



      class DirectPatchConvolution : public PatchConvolution
      {
      public:
        DirectPatchConvolution(const modal::PatchModel &model, const double dt,
                               const unsigned int n_kernel_)
          : PatchConvolution(model.n_points(), dt)
          , n_kernel(std::max(2u, n_kernel_))
          , preload_model(model, dt, 1)
        {
          const PoleWeights w(model, dt);
          psi = w.influence();
          // Lag m >= 1: the loads of step n - m seen at t_{n+1} are those of
          // the current step's influence, decayed over m steps:
          // W_m = Re sum_k c_k e^{lambda_k m dt} w_k, w = (alpha, beta_a, beta_b, 1).
          // All lags at once as one product: rows (lag, generator), columns
          // (i, j), inner dimension the real and imaginary part of each pole.
          const unsigned int n_terms = model.n_terms();
          const Eigen::Index n_lags  = n_kernel - 1;
          Eigen::MatrixXd    Z(n_lags * 4, 2 * n_terms);
          for (Eigen::Index m = 0; m < n_lags; ++m)
            for (unsigned int k = 0; k < n_terms; ++k)
              {
                const std::complex<double> decay = std::exp(model.lambda[k] * double(m + 1) * dt);
                const std::complex<double> gen[4] = {w.alpha[k], w.beta_a[k], w.beta_b[k], 1.};
                for (unsigned int g = 0; g < 4; ++g)
                  {
                    const std::complex<double> z = decay * gen[g];
                    Z(4 * m + g, k)              = z.real();
                    Z(4 * m + g, n_terms + k)    = -z.imag();
                  }
              }
          for (const auto *c : {&w.cu, &w.cv})
            {
              Eigen::MatrixXd C(2 * n_terms, Eigen::Index(n_p) * n_p);
              for (unsigned int k = 0; k < n_terms; ++k)
                {
                  // Column index i + n_p * j: a column-major n_p x n_p block.
                  C.row(k)           = Eigen::Map<const Eigen::MatrixXd>(
                                         Eigen::MatrixXd((*c)[k].real()).data(), 1,
                                         Eigen::Index(n_p) * n_p);
                  C.row(n_terms + k) = Eigen::Map<const Eigen::MatrixXd>(
                                         Eigen::MatrixXd((*c)[k].imag()).data(), 1,
                                         Eigen::Index(n_p) * n_p);
                }
              const Eigen::MatrixXd W = Z * C;
              // Store per lag one n_p x 4 n_p block [W_g0 W_g1 W_g2 W_g3].
              auto &target = (c == &w.cu) ? Wu : Wv;
              target.assign(n_lags, Eigen::MatrixXd(n_p, 4 * n_p));
              for (Eigen::Index m = 0; m < n_lags; ++m)
                for (unsigned int g = 0; g < 4; ++g)
                  target[m].middleCols(g * n_p, n_p) =
                    Eigen::Map<const Eigen::MatrixXd>(W.row(4 * m + g).eval().data(), n_p, n_p);
            }
          past.assign(n_lags, Eigen::VectorXd::Zero(4 * n_p));
        }

        void
        history(Eigen::VectorXd &u, Eigen::VectorXd &v) override
        {
          preload_model.history(u, v);
          const std::size_t n_lags = std::min<std::size_t>(n_recorded, past.size());
          for (std::size_t m = 0; m < n_lags; ++m)
            {
              // past[(head - 1 - m) mod size] is the step m + 1 steps back.
              const std::size_t slot = (head + past.size() - 1 - m) % past.size();
              u.noalias() += Wu[m] * past[slot];
              v.noalias() += Wv[m] * past[slot];
            }
        }

        void
        advance(const PatchLoad &load) override
        {
          Eigen::VectorXd &slot = past[head];
          for (unsigned int g = 0; g < 4; ++g)
            slot.segment(g * n_p, n_p) = load.component[g];
          head = (head + 1) % past.size();
          ++n_recorded;
          // The preload decays freely.
          preload_model.advance(PatchLoad(n_p));
        }

        void
        preload(const Eigen::VectorXd &q0) override
        {
          preload_model.preload(q0);
        }

        std::string
        name() const override
        {
          return "direct";
        }

      private:
        unsigned int                 n_kernel;
        ModalPatchConvolution        preload_model;
        std::vector<Eigen::MatrixXd> Wu, Wv;
        std::vector<Eigen::VectorXd> past;
        std::size_t                  head = 0, n_recorded = 0;
      };
    } // namespace



    std::unique_ptr<PatchConvolution>
    make_modal_patch_convolution(const modal::PatchModel &model, const double dt,
                                 const unsigned int n_threads)
    {
      return std::make_unique<ModalPatchConvolution>(model, dt, n_threads);
    }



    std::unique_ptr<PatchConvolution>
    make_direct_patch_convolution(const modal::PatchModel &model, const double dt,
                                  const unsigned int n_kernel)
    {
      return std::make_unique<DirectPatchConvolution>(model, dt, n_kernel);
    }



    namespace
    {
      convolution::Influence
      point_influence(const PatchInfluence &psi, const unsigned int j)
      {
        convolution::Influence p;
        for (unsigned int g = 0; g < 4; ++g)
          {
            p.u[g] = psi.u[g](j, j);
            p.v[g] = psi.v[g](j, j);
          }
        return p;
      }

      std::array<double, 4>
      components(const convolution::StepLoad &l)
      {
        return {{l.impulse_start, l.start, l.end, l.impulse_end}};
      }
    } // namespace



    PatchKinematicContact::PatchKinematicContact(const PatchInfluence &psi_)
      : psi(psi_)
    {
      const unsigned int n = psi.u[0].rows();
      if (!psi.instantaneous)
        for (unsigned int j = 0; j < n; ++j)
          rules.emplace_back(point_influence(psi, j));
      active.assign(n, false);
      shapes.assign(n, {{1., 0., 0., 0.}});
    }



    void
    PatchKinematicContact::set_force(const Eigen::VectorXd &q)
    {
      previous_end = q;
      for (unsigned int j = 0; j < q.size(); ++j)
        active[j] = q[j] > 0.;
    }



    PatchStepReport
    PatchKinematicContact::solve_continuous(const Eigen::VectorXd &uh,
                                            const Eigen::VectorXd &d,
                                            PatchLoad             &load)
    {
      // The load is linear over the step from the last step's end value a
      // (known) to b (unknown): u(t_{n+1}) = u^h + Psi_start a + Psi_end b.
      const unsigned int n = uh.size();
      for (unsigned int j = 0; j < n; ++j)
        if (!std::isfinite(uh[j]) || !std::isfinite(d[j]))
          throw NumericalError("patch contact: the history term or the road demand at point " +
                               std::to_string(j) + " is not finite (u^h = " +
                               format_short(uh[j]) + ", d = " + format_short(d[j]) + ")");
      if (previous_end.size() != n)
        previous_end = Eigen::VectorXd::Zero(n);
      Eigen::VectorXd q = uh + psi.u[1] * previous_end - d;
      if (!q.allFinite())
        throw NumericalError("patch contact: the force of the last step is not finite (largest "
                             "|q| " + format_short(previous_end.cwiseAbs().maxCoeff()) + ")");
      const LcpResult lcp = solve_lcp(psi.u[2], q, active);
      if (!lcp.z.allFinite())
        throw NumericalError("patch contact: the complementarity solve returned a force that is "
                             "not finite (" + (lcp.converged ? std::string("converged") :
                                                               lcp.message) + ")");
      PatchStepReport       report;
      report.outer_iterations = 1;
      report.lcp_iterations   = lcp.iterations;
      report.converged        = lcp.converged;
      if (!lcp.converged)
        report.message = "LCP: " + lcp.message;
      for (auto &c : load.component)
        c.setZero();
      load.component[1] = previous_end;
      load.component[2] = lcp.z.cwiseMax(0.);
      previous_end      = load.component[2];
      for (unsigned int j = 0; j < n; ++j)
        if (lcp.z[j] > 0.)
          ++report.n_contact;
      // Moved, not copied: no allocation per step for the record.
      report.lcp_matrix = &psi.u[2];
      report.lcp_q      = std::move(q);
      report.lcp_z      = std::move(lcp.z);
      return report;
    }



    PatchStepReport
    PatchKinematicContact::solve(const Eigen::VectorXd &uh, const Eigen::VectorXd &vh,
                                 const Eigen::VectorXd &d, const Eigen::VectorXd &dd,
                                 PatchLoad &load)
    {
      const unsigned int n = uh.size();
      if (psi.instantaneous)
        return solve_continuous(uh, d, load);
      PatchStepReport    report;
      for (unsigned int j = 0; j < n; ++j)
        if (!std::isfinite(uh[j]) || !std::isfinite(vh[j]) || !std::isfinite(d[j]) ||
            !std::isfinite(dd[j]))
          throw NumericalError("patch contact: the history term or the road demand at point " +
                               std::to_string(j) + " is not finite (u^h = " +
                               format_short(uh[j]) + ", d = " + format_short(d[j]) + ")");

      // What each point still needs, given the loads x of the others.
      Eigen::MatrixXd x = Eigen::MatrixXd::Zero(n, 4); // x(j, g)
      const auto      take_rule = [&](const Eigen::VectorXd &du, const Eigen::VectorXd &dv,
                                 const std::vector<bool> &which, double &change) {
        change = 0.;
        for (unsigned int j = 0; j < n; ++j)
          {
            if (!which[j])
              continue;
            const KinematicStep step = rules[j].solve(du[j], dv[j]);
            const auto          c    = components(step.load);
            const double        sum  = std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]) + std::abs(c[3]);
            std::array<double, 4> s{{1., 0., 0., 0.}};
            if (sum > 0.)
              for (unsigned int g = 0; g < 4; ++g)
                s[g] = c[g] / sum;
            for (unsigned int g = 0; g < 4; ++g)
              change = std::max(change, std::abs(s[g] - shapes[j][g]));
            shapes[j] = s;
          }
      };

      double          change = 0.;
      Eigen::VectorXd du = d - uh, dv = dd - vh;
      take_rule(du, dv, std::vector<bool>(n, true), change);

      Eigen::VectorXd       q = uh - d;
      Eigen::MatrixXd      &M = lcp_matrix;
      M.resize(n, n);
      LcpResult             lcp;
      constexpr unsigned int max_rounds = 50;
      for (unsigned int round = 0; round < max_rounds; ++round)
        {
          report.outer_iterations = round + 1;
          for (unsigned int j = 0; j < n; ++j)
            {
              M.col(j).setZero();
              for (unsigned int g = 0; g < 4; ++g)
                if (shapes[j][g] != 0.)
                  M.col(j) += shapes[j][g] * psi.u[g].col(j);
            }
          lcp = solve_lcp(M, q, active);
          report.lcp_iterations += lcp.iterations;
          for (unsigned int j = 0; j < n; ++j)
            for (unsigned int g = 0; g < 4; ++g)
              x(j, g) = std::max(lcp.z[j], 0.) * shapes[j][g];
          if (!lcp.converged)
            {
              report.converged = false;
              report.message   = "LCP: " + lcp.message;
              break;
            }
          // Coupled demands: subtract what the others' loads do at each point.
          Eigen::VectorXd u_all = Eigen::VectorXd::Zero(n), v_all = Eigen::VectorXd::Zero(n);
          for (unsigned int g = 0; g < 4; ++g)
            {
              u_all += psi.u[g] * x.col(g);
              v_all += psi.v[g] * x.col(g);
            }
          std::vector<bool> in_contact(n);
          for (unsigned int j = 0; j < n; ++j)
            {
              in_contact[j] = lcp.z[j] > 0.;
              double own_u = 0., own_v = 0.;
              for (unsigned int g = 0; g < 4; ++g)
                {
                  own_u += psi.u[g](j, j) * x(j, g);
                  own_v += psi.v[g](j, j) * x(j, g);
                }
              du[j] = d[j] - uh[j] - (u_all[j] - own_u);
              dv[j] = dd[j] - vh[j] - (v_all[j] - own_v);
            }
          take_rule(du, dv, in_contact, change);
          if (change <= 1e-9)
            break;
          if (round + 1 == max_rounds)
            {
              report.converged = false;
              report.message   = "the load shapes still changed by " + format_short(change) +
                               " after " + std::to_string(max_rounds) + " rounds";
            }
        }

      // Final loads and the report.
      double scale = 0.;
      for (unsigned int j = 0; j < n; ++j)
        scale = std::max(scale, std::abs(dd[j] - vh[j]));
      Eigen::VectorXd v_end = vh;
      for (unsigned int g = 0; g < 4; ++g)
        {
          load.component[g] = x.col(g);
          v_end += psi.v[g] * x.col(g);
        }
      for (unsigned int j = 0; j < n; ++j)
        if (lcp.z[j] > 0.)
          {
            ++report.n_contact;
            const KinematicStep step = rules[j].solve(du[j], dv[j]);
            if (step.branch == KinematicBranch::fallback)
              ++report.n_fallback;
            else
              report.velocity_residual =
                std::max(report.velocity_residual,
                         std::abs(v_end[j] - dd[j]) / std::max(scale, 1e-300));
          }
      report.lcp_matrix = &M;
      report.lcp_q      = std::move(q);
      report.lcp_z      = std::move(lcp.z);
      return report;
    }



    RollingSummary
    roll(PatchConvolution                                                              &conv,
         const std::function<void(double, Eigen::VectorXd &, Eigen::VectorXd &)> &demand,
         const unsigned int                                                       n_steps,
         const Eigen::VectorXd                                                   &start_force,
         const std::function<void(const RollingStep &)>                          &observe)
    {
      const unsigned int n  = conv.n_points();
      const double       dt = conv.time_step();
      if (start_force.size() != 0 && start_force.size() != n)
        throw InputError("roll: the start force has " + std::to_string(start_force.size()) +
                         " entries for " + std::to_string(n) + " points");
      PatchKinematicContact solver(conv.influence());
      if (start_force.size() != 0)
        {
          conv.preload(start_force);
          solver.set_force(start_force);
        }
      PatchLoad       load(n);
      Eigen::VectorXd uh(n), vh(n), dd(n);
      RollingSummary  summary;
      RollingStep     s;
      s.d.resize(n);
      summary.steps = n_steps;
      for (unsigned int k = 0; k < n_steps; ++k)
        {
          s.step = k;
          s.time = (k + 1) * dt;
          conv.history(uh, vh);
          demand(s.time, s.d, dd);
          s.report = solver.solve(uh, vh, s.d, dd, load);
          conv.advance(load);
          s.u = uh;
          for (unsigned int g = 0; g < 4; ++g)
            s.u += conv.influence().u[g] * load.component[g];
          s.force = load.impulse(dt) / dt;
          if (!s.force.allFinite() || !s.u.allFinite())
            throw NumericalError("rolling contact: the contact forces or displacements are not "
                                 "finite at step " + std::to_string(k) + " (t = " +
                                 format_short(s.time) + " s)" +
                                 (s.report.converged ? std::string() :
                                                       "; the contact solve had failed: " +
                                                         s.report.message));
          if (!s.report.converged)
            {
              if (summary.failed_steps == 0)
                summary.first_failure = "step " + std::to_string(k) + " (t = " +
                                        format_short(s.time) + " s): " + s.report.message;
              ++summary.failed_steps;
            }
          summary.fallback_points += s.report.n_fallback;
          const double fraction        = double(s.report.n_contact) / n;
          summary.min_contact_fraction = std::min(summary.min_contact_fraction, fraction);
          summary.max_contact_fraction = std::max(summary.max_contact_fraction, fraction);
          summary.impulse += s.force.sum() * dt;
          summary.max_penetration = std::max(summary.max_penetration, (s.d - s.u).maxCoeff());
          if (observe)
            observe(s);
        }
      return summary;
    }



    StaticContact
    solve_static_contact(const Eigen::MatrixXd &G0, const Eigen::VectorXd &d0,
                         const double total_load, const double delta)
    {
      const unsigned int n = d0.size();
      std::vector<bool>  active(n, false);
      const auto         solve_at = [&](const double shift, StaticContact &result) {
        const Eigen::VectorXd q   = -(d0.array() + shift).matrix();
        const LcpResult       lcp = solve_lcp(G0, q, active);
        if (!lcp.converged)
          throw NumericalError("static contact: the complementarity solve failed at indentation " +
                               format_short(shift) + " m: " + lcp.message);
        result.q         = lcp.z;
        result.u         = G0 * lcp.z;
        result.delta     = shift;
        result.n_contact = 0;
        for (unsigned int j = 0; j < n; ++j)
          if (lcp.z[j] > 0.)
            ++result.n_contact;
        return lcp.z.sum();
      };

      StaticContact result;
      if (!(total_load > 0.))
        {
          solve_at(delta, result);
          return result;
        }
      // The total force grows monotonically with the indentation: bracket it
      // and bisect.
      double low = -d0.maxCoeff(), high = low + 1e-4;
      for (unsigned int k = 0; solve_at(high, result) < total_load; ++k)
        {
          if (k == 60)
            throw NumericalError("static contact: no indentation carries the load " +
                                 format_short(total_load) + " N");
          high = low + 2. * (high - low);
        }
      for (unsigned int k = 0; k < 100 && high - low > 1e-13 * std::max(1e-3, std::abs(high));
           ++k)
        {
          const double mid = 0.5 * (low + high);
          (solve_at(mid, result) < total_load ? low : high) = mid;
        }
      const double load = solve_at(high, result);
      if (std::abs(load - total_load) > 1e-6 * total_load)
        {
          // The force is linear in the indentation once the active set is
          // fixed: one secant step on the last bracket lands on it.
          StaticContact at_low;
          const double  load_low = solve_at(low, at_low);
          const double  shift    = low + (total_load - load_low) * (high - low) / (load - load_low);
          solve_at(shift, result);
        }
      return result;
    }
  } // namespace contact
} // namespace greentread
