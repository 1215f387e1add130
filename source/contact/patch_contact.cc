#include <greentread/base/exceptions.h>
#include <greentread/contact/candidate_set.h>
#include <greentread/contact/patch_contact.h>
#include <greentread/contact/projected_cg.h>

#include <cmath>
#include <limits>
#include <utility>

namespace greentread
{
  namespace contact
  {
    namespace
    {
      convolution::Influence
      point_influence(const convolution::PatchInfluence &psi, const unsigned int j)
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



    PatchKinematicContact::PatchKinematicContact(const convolution::PatchInfluence &psi_,
                                                 const unsigned int                 n)
        : psi(psi_)
        , matrix_free(static_cast<bool>(psi_.add_u))
    {
      if (matrix_free && !psi.instantaneous)
        throw InputError("patch contact: a matrix-free influence needs an instantaneous "
                         "compliance (a continuous contact force)");
      if (matrix_free && psi.end_norm > 0.)
        end_norm = psi.end_norm;
      else if (matrix_free)
        end_norm = operator_norm(
          [&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
            y.setZero(x.size());
            psi.add_u(2, x, y);
          },
          n);
      else if (psi.instantaneous)
        end_norm = lcp_matrix_norm(psi.u[2]);
      else
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
    PatchKinematicContact::solve_continuous(const Eigen::VectorXd  &uh,
                                            const Eigen::VectorXd  &d,
                                            convolution::PatchLoad &load)
    {
      // The load is linear over the step from the last step's end value a
      // (known) to b (unknown): u(t_{n+1}) = u^h + Psi_start a + Psi_end b.
      const unsigned int n = uh.size();
      for (unsigned int j = 0; j < n; ++j)
        if (!std::isfinite(uh[j]) || !std::isfinite(d[j]))
          throw NumericalError("patch contact: the history term or the road demand at point " +
                               std::to_string(j) + " is not finite (u^h = " + format_short(uh[j]) +
                               ", d = " + format_short(d[j]) + ")");
      if (previous_end.size() != n)
        previous_end = Eigen::VectorXd::Zero(n);
      Eigen::VectorXd q = uh - d;
      convolution::add_influence(psi, 1, previous_end, q);
      if (!q.allFinite())
        throw NumericalError("patch contact: the force of the last step is not finite (largest "
                             "|q| " +
                             format_short(previous_end.cwiseAbs().maxCoeff()) + ")");
      LcpResult          lcp;
      CandidateSetReport candidates;
      bool               candidate_set = false;
      if (matrix_free)
        {
          ProjectedCgOptions options;
          options.operator_norm     = end_norm;
          options.tolerance         = psi.tolerance;
          const SymmetricOperator W = [&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
            y.setZero(x.size());
            psi.add_u(2, x, y);
          };
          if (psi.block_u)
            {
              lcp = solve_lcp_candidate_set(W, psi.block_u, q, previous_end, options, &candidates);
              candidate_set = true;
            }
          else
            lcp = solve_lcp_projected_cg(W, q, previous_end, options);
        }
      else
        {
          LcpOptions options;
          options.matrix_norm = end_norm;
          lcp                 = solve_lcp(psi.u[2], q, active, options);
        }
      if (!lcp.z.allFinite())
        throw NumericalError("patch contact: the complementarity solve returned a force that is "
                             "not finite (" +
                             (lcp.converged ? std::string("converged") : lcp.message) + ")");
      PatchStepReport report;
      report.outer_iterations = 1;
      report.lcp_iterations   = lcp.iterations;
      report.converged        = lcp.converged;
      report.candidates       = candidates;
      report.candidate_set    = candidate_set;
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
      report.lcp_matrix    = matrix_free ? nullptr : &psi.u[2];
      report.lcp_q         = std::move(q);
      report.lcp_z         = std::move(lcp.z);
      report.lcp_projected = lcp.projected;
      return report;
    }



    PatchStepReport
    PatchKinematicContact::solve(const Eigen::VectorXd  &uh,
                                 const Eigen::VectorXd  &vh,
                                 const Eigen::VectorXd  &d,
                                 const Eigen::VectorXd  &dd,
                                 convolution::PatchLoad &load)
    {
      const unsigned int n = uh.size();
      if (psi.instantaneous)
        return solve_continuous(uh, d, load);
      PatchStepReport report;
      for (unsigned int j = 0; j < n; ++j)
        if (!std::isfinite(uh[j]) || !std::isfinite(vh[j]) || !std::isfinite(d[j]) ||
            !std::isfinite(dd[j]))
          throw NumericalError("patch contact: the history term or the road demand at point " +
                               std::to_string(j) + " is not finite (u^h = " + format_short(uh[j]) +
                               ", d = " + format_short(d[j]) + ")");

      // What each point still needs, given the loads x of the others.
      Eigen::MatrixXd x         = Eigen::MatrixXd::Zero(n, 4); // x(j, g)
      const auto      take_rule = [&](const Eigen::VectorXd &du, const Eigen::VectorXd &dv,
                                 const std::vector<bool> &which, double &change) {
        change = 0.;
        for (unsigned int j = 0; j < n; ++j)
          {
            if (!which[j])
              continue;
            const KinematicStep step = rules[j].solve(du[j], dv[j]);
            const auto          c    = components(step.load);
            const double sum = std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]) + std::abs(c[3]);
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

      Eigen::VectorXd  q = uh - d;
      Eigen::MatrixXd &M = lcp_matrix;
      M.resize(n, n);
      LcpResult              lcp;
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
              report.velocity_residual = std::max(
                report.velocity_residual, std::abs(v_end[j] - dd[j]) / std::max(scale, 1e-300));
          }
      report.lcp_matrix    = &M;
      report.lcp_q         = std::move(q);
      report.lcp_z         = std::move(lcp.z);
      report.lcp_projected = lcp.projected;
      return report;
    }



    RollingSummary
    roll(convolution::PatchConvolution                                           &conv,
         const std::function<void(double, Eigen::VectorXd &, Eigen::VectorXd &)> &demand,
         const unsigned int                                                       n_steps,
         const Eigen::VectorXd                                                   &start_force,
         const std::function<void(const RollingStep &)>                          &observe,
         const std::function<unsigned int(unsigned int)>                         &more_steps)
    {
      const unsigned int n  = conv.n_points();
      const double       dt = conv.time_step();
      if (start_force.size() != 0 && start_force.size() != n)
        throw InputError("roll: the start force has " + std::to_string(start_force.size()) +
                         " entries for " + std::to_string(n) + " points");
      PatchKinematicContact solver(conv.influence(), n);
      if (start_force.size() != 0)
        {
          conv.preload(start_force);
          solver.set_force(start_force);
        }
      convolution::PatchLoad load(n);
      Eigen::VectorXd        uh(n), vh(n), dd(n);
      RollingSummary         summary;
      RollingStep            s;
      s.d.resize(n);
      unsigned int total = n_steps, last_candidates = 0;
      for (unsigned int k = 0;; ++k)
        {
          // At the record's end: on, if asked for more.
          if (k == total)
            {
              const unsigned int more = more_steps ? more_steps(total) : 0;
              if (more == 0)
                break;
              total += more;
            }
          s.step = k;
          s.time = (k + 1) * dt;
          // A continuous force (an instantaneous compliance) is solved on the
          // displacement alone: the history's velocity is not formed, and
          // vh stays NaN so that any use of it would show.
          if (conv.influence().instantaneous)
            {
              conv.history_u(uh);
              vh.setConstant(std::numeric_limits<double>::quiet_NaN());
            }
          else
            conv.history(uh, vh);
          demand(s.time, s.d, dd);
          s.report = solver.solve(uh, vh, s.d, dd, load);
          conv.advance(load);
          s.u = uh;
          for (unsigned int g = 0; g < 4; ++g)
            convolution::add_influence(conv.influence(), g, load.component[g], s.u);
          s.force     = load.impulse(dt) / dt;
          s.end_force = load.component[2];
          if (!s.force.allFinite() || !s.u.allFinite())
            throw NumericalError("rolling contact: the contact forces or displacements are not "
                                 "finite at step " +
                                 std::to_string(k) + " (t = " + format_short(s.time) + " s)" +
                                 (s.report.converged ?
                                    std::string() :
                                    "; the contact solve had failed: " + s.report.message));
          if (!s.report.converged)
            {
              if (summary.failed_steps == 0)
                summary.first_failure = "step " + std::to_string(k) +
                                        " (t = " + format_short(s.time) +
                                        " s): " + s.report.message;
              ++summary.failed_steps;
            }
          summary.fallback_points += s.report.n_fallback;
          const double fraction        = double(s.report.n_contact) / n;
          summary.min_contact_fraction = std::min(summary.min_contact_fraction, fraction);
          summary.max_contact_fraction = std::max(summary.max_contact_fraction, fraction);
          summary.impulse += s.force.sum() * dt;
          summary.max_penetration = std::max(summary.max_penetration, (s.d - s.u).maxCoeff());
          if (s.report.candidate_set)
            {
              const auto &set = s.report.candidates;
              ++summary.candidate_steps;
              summary.max_candidates = std::max(summary.max_candidates, set.end);
              summary.grown_steps += set.end > set.start;
              summary.shrunk_steps += k > 0 && set.start < last_candidates;
              summary.whole_grid_steps += set.whole_grid;
              last_candidates = set.end;
            }
          if (observe)
            observe(s);
        }
      summary.steps = total;
      return summary;
    }



    StaticContact
    solve_static_contact(const Eigen::MatrixXd &G0,
                         const Eigen::VectorXd &d0,
                         const double           total_load,
                         const double           delta)
    {
      std::vector<bool> active(d0.size(), false);
      return solve_static_contact(
        [&](const Eigen::VectorXd &c) {
          return solve_lcp(G0, c, active);
        },
        d0, total_load, delta);
    }



    StaticContact
    solve_static_contact(const StaticSolve     &solve,
                         const Eigen::VectorXd &d0,
                         const double           total_load,
                         const double           delta)
    {
      const unsigned int n        = d0.size();
      const auto         solve_at = [&](const double shift, StaticContact &result) {
        const Eigen::VectorXd q   = -(d0.array() + shift).matrix();
        const LcpResult       lcp = solve(q);
        if (!lcp.converged)
          throw NumericalError("static contact: the complementarity solve failed at indentation " +
                                       format_short(shift) + " m: " + lcp.message);
        result.q         = lcp.z;
        result.u         = lcp.w - q;
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
      for (unsigned int k = 0; k < 100 && high - low > 1e-13 * std::max(1e-3, std::abs(high)); ++k)
        {
          const double mid                                  = 0.5 * (low + high);
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
