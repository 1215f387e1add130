#include <greentread/base/exceptions.h>
#include <greentread/base/job_runner.h>
#include <greentread/radiation/surface_mobility.h>
#include <greentread/synthesis/harmonic_modes.h>
#include <greentread/synthesis/ring_modes.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/numbers.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>

namespace greentread
{
  namespace radiation
  {
    namespace
    {
      /// sin x / x.
      double
      sinc(const double x)
      {
        return std::abs(x) < 1e-8 ? 1. - x * x / 6. : std::sin(x) / x;
      }
    } // namespace

    SurfaceMobility::SurfaceMobility(const fe::HarmonicSection    &section,
                                     const periodic::ContactPatch &patch,
                                     const TyreSurface            &surface,
                                     const double                  cutoff,
                                     const unsigned int            n_harmonics,
                                     const bool                    couple_damping)
        : cell_segment(surface.segment)
        , cell_angle(surface.angle)
        , n_strips(patch.points_across)
        , cell_arc(surface.arc)
        , point_arc(patch.arc)
    {
      if (patch.load != periodic::PointLoad::tributary_area)
        throw InputError("the tyre's surface mobility needs 'Green's functions/Point load' = "
                         "tributary area; a point force's series round the ring does not "
                         "converge");
      // The points' strips across the tread, as the harmonic ring loads
      // them, and their angles from the patch centre: x along the tread
      // over the radius the patch's arcs are measured on.
      Eigen::MatrixXd strips(section.size(), n_strips);
      for (unsigned int j = 0; j < n_strips; ++j)
        {
          const double y    = patch.points[j].y;
          const auto [w, W] = section.tread_strip(y - 0.5 * patch.dy, y + 0.5 * patch.dy);
          strips.col(j)     = w / W;
        }
      const double radius = patch.dx / patch.arc;
      for (std::size_t p = 0; p < patch.points.size(); ++p)
        {
          point_strip.push_back(static_cast<int>(p % n_strips));
          point_angle.push_back(patch.points[p].x / radius);
        }

      const Eigen::MatrixXd segment_loads = section.surface_segments(surface.section_line).first;
      const Eigen::Index    S = segment_loads.cols(), J = n_strips;
      Eigen::MatrixXd       loads(section.size(), S + J);
      loads << segment_loads, strips;

      harmonics.resize(n_harmonics);
      const unsigned int n_threads = std::max(1u, dealii::MultithreadInfo::n_threads());
      base::for_each_index(n_harmonics, n_threads, [&](const std::size_t index, unsigned int) {
        const auto                 n     = static_cast<unsigned int>(index);
        synthesis::WavenumberModes modes = synthesis::harmonic_modes(section, n, cutoff);
        const Eigen::MatrixXd      seen  = modes.omega.size() > 0 ?
                                             Eigen::MatrixXd(modes.shapes.real().transpose() * loads) :
                                             Eigen::MatrixXd(0, S + J);
        modes.shapes.resize(0, 0);
        const synthesis::PointModes at = synthesis::coupled_point_modes(
          modes, seen.cast<std::complex<double>>(), 1., true, couple_damping);
        Harmonic &h     = harmonics[n];
        h.omega         = at.omega;
        h.damping_ratio = at.damping_ratio;
        h.coupled       = at.coupled;
        const Eigen::MatrixXcd shapes =
          at.shapes.cast<std::complex<double>>() +
          std::complex<double>(0., 1.) * at.shapes_imag.cast<std::complex<double>>();
        h.at_segments = shapes.leftCols(S);
        h.at_strips   = shapes.rightCols(J);

        // The static residual: the direct H_n(0) less the modes' part.
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> stiffness(section.stiffness(n));
        if (stiffness.info() != Eigen::Success)
          throw NumericalError("the surface mobility's harmonic " + std::to_string(n) +
                               ": the section's stiffness could not be factored");
        const Eigen::MatrixXd static_response = stiffness.solve(strips);
        h.residual =
          segment_loads.transpose() * static_response - modal_part(h, h.at_segments, 0.).real();
        h.strip_residual =
          strips.transpose() * static_response - modal_part(h, h.at_strips, 0.).real();
      });
    }



    Eigen::MatrixXcd
    SurfaceMobility::modal_part(const Harmonic &h, const Eigen::MatrixXcd &left, const double omega)
    {
      using Complex          = std::complex<double>;
      const Eigen::Index m   = h.omega.size();
      Eigen::VectorXcd   den = Eigen::VectorXcd::Zero(m);
      Eigen::MatrixXcd   out = Eigen::MatrixXcd::Zero(left.cols(), h.at_strips.cols());
      if (m == 0)
        return out;
      if (!h.coupled)
        {
          for (Eigen::Index k = 0; k < m; ++k)
            den(k) = 1. / Complex(h.omega(k) * h.omega(k) - omega * omega,
                                  2. * h.damping_ratio(k) * h.omega(k) * omega);
          return left.transpose() * den.asDiagonal() * h.at_strips;
        }
      // psi psi^T / (2 j w_d (j w - l)) - conj(psi psi^T) / (2 j w_d (j w - conj l)).
      Eigen::VectorXcd conj_den(m);
      for (Eigen::Index k = 0; k < m; ++k)
        {
          const double  xi = h.damping_ratio(k), w = h.omega(k);
          const Complex l(-xi * w, w * std::sqrt(1. - xi * xi));
          const Complex jw(0., omega), twice(0., 2. * l.imag());
          den(k)      = 1. / (twice * (jw - l));
          conj_den(k) = -1. / (twice * (jw - std::conj(l)));
        }
      out = left.transpose() * den.asDiagonal() * h.at_strips;
      out += left.conjugate().transpose() * conj_den.asDiagonal() * h.at_strips.conjugate();
      return out;
    }



    Eigen::MatrixXcd
    SurfaceMobility::section_transfer(const unsigned int n, const double omega) const
    {
      const Harmonic &h = harmonics.at(n);
      return modal_part(h, h.at_segments, omega) + h.residual.cast<std::complex<double>>();
    }



    Eigen::MatrixXcd
    SurfaceMobility::strip_transfer(const unsigned int n, const double omega) const
    {
      const Harmonic &h = harmonics.at(n);
      return modal_part(h, h.at_strips, omega) + h.strip_residual.cast<std::complex<double>>();
    }



    unsigned int
    SurfaceMobility::n_modes() const
    {
      unsigned int total = 0;
      for (const auto &h : harmonics)
        total += static_cast<unsigned int>(h.omega.size());
      return total;
    }



    Eigen::MatrixXcd
    SurfaceMobility::spread(const double            omega,
                            const Eigen::MatrixXcd &forces,
                            const bool              to_points) const
    {
      using Complex = std::complex<double>;
      const auto P  = static_cast<Eigen::Index>(point_angle.size());
      if (forces.rows() != P)
        throw NumericalError("the surface mobility has " + std::to_string(P) +
                             " points; forces given at " + std::to_string(forces.rows()));
      // Where the velocity goes: each row's segment (or strip) and angle.
      const std::vector<int>    &row_line  = to_points ? point_strip : cell_segment;
      const std::vector<double> &row_angle = to_points ? point_angle : cell_angle;
      const double               row_arc   = to_points ? point_arc : cell_arc;
      const auto                 R         = static_cast<Eigen::Index>(row_line.size());
      const Eigen::Index         K         = forces.cols();
      Eigen::MatrixXcd           v         = Eigen::MatrixXcd::Zero(R, K);
      for (unsigned int n = 0; n < harmonics.size(); ++n)
        {
          const double weight = (n == 0 ? 1. : 2.) / (2. * dealii::numbers::PI) *
                                sinc(0.5 * n * row_arc) * sinc(0.5 * n * point_arc);
          // cos(n (a - b)) = (e^{jn(a - b)} + e^{-jn(a - b)}) / 2: the forces'
          // content per strip at e^{-jn theta} (plus) and e^{+jn theta} (minus).
          Eigen::MatrixXcd plus = Eigen::MatrixXcd::Zero(n_strips, K), minus = plus;
          for (Eigen::Index q = 0; q < P; ++q)
            {
              const Complex e = std::polar(1., n * point_angle[q]);
              plus.row(point_strip[q]) += std::conj(e) * forces.row(q);
              minus.row(point_strip[q]) += e * forces.row(q);
            }
          const Eigen::MatrixXcd H =
            (0.5 * weight) * (to_points ? strip_transfer(n, omega) : section_transfer(n, omega));
          const Eigen::MatrixXcd u_plus = H * plus, u_minus = H * minus;
          for (Eigen::Index c = 0; c < R; ++c)
            if (row_line[c] >= 0)
              {
                const Complex e = std::polar(1., n * row_angle[c]);
                v.row(c) += e * u_plus.row(row_line[c]) + std::conj(e) * u_minus.row(row_line[c]);
              }
        }
      return Complex(0., omega) * v;
    }



    Eigen::MatrixXcd
    SurfaceMobility::velocity(const double omega, const Eigen::MatrixXcd &forces) const
    {
      return spread(omega, forces, false);
    }



    Eigen::MatrixXcd
    SurfaceMobility::point_velocity(const double omega, const Eigen::MatrixXcd &forces) const
    {
      return spread(omega, forces, true);
    }



    Eigen::MatrixXcd
    SurfaceMobility::at(const double omega) const
    {
      return velocity(omega, Eigen::MatrixXcd::Identity(n_points(), n_points()));
    }
  } // namespace radiation
} // namespace greentread
