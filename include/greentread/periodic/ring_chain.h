#pragma once

#include <greentread/periodic/contact_patch.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <vector>

/**
 * @file
 * The numbering of a chain of reference cells: the full ring of the
 * `full-ring` Green's functions, the contact cells of Eq. (49), and the
 * time-domain reference of greentread/reference/newmark_ring.h.
 */

namespace greentread
{
  namespace periodic
  {
    /**
     * A chain of cells: unknowns are the faces 0 .. n_faces - 1, then the
     * interiors 0 .. n_chain - 1. Cell m joins face m, interior m and face
     * (m + 1) mod n_faces: an open chain has n_chain + 1 faces, a closed
     * ring n_chain.
     */
    struct RingChain
    {
      unsigned int n_face, n_interior, n_chain, n_faces;

      unsigned int
      size() const
      {
        return n_faces * n_face + n_chain * n_interior;
      }

      /// The chain index of DoF i of cell m's [L, I, R].
      unsigned int
      index(const unsigned int m, const unsigned int i) const
      {
        if (i < n_face)
          return m * n_face + i;
        if (i < n_face + n_interior)
          return n_faces * n_face + m * n_interior + (i - n_face);
        return ((m + 1) % n_faces) * n_face + (i - n_face - n_interior);
      }

      /// The entries of the cell matrix @p D [L, I, R] in every cell of the chain.
      template <typename Number>
      void
      add(const Eigen::SparseMatrix<Number> &D, std::vector<Eigen::Triplet<Number>> &entries) const
      {
        for (unsigned int m = 0; m < n_chain; ++m)
          for (int c = 0; c < D.outerSize(); ++c)
            for (typename Eigen::SparseMatrix<Number>::InnerIterator it(D, c); it; ++it)
              entries.emplace_back(index(m, it.row()), index(m, it.col()), it.value());
      }

      /// The cell matrix @p D assembled over the chain.
      template <typename Number>
      Eigen::SparseMatrix<Number>
      assemble(const Eigen::SparseMatrix<Number> &D) const
      {
        std::vector<Eigen::Triplet<Number>> entries;
        add(D, entries);
        Eigen::SparseMatrix<Number> A(size(), size());
        A.setFromTriplets(entries.begin(), entries.end());
        A.makeCompressed();
        return A;
      }

      /// The contact points' unit loads, one column each (ContactPoint::load).
      Eigen::MatrixXd
      loads(const ContactPatch &patch) const
      {
        Eigen::MatrixXd B = Eigen::MatrixXd::Zero(size(), patch.points.size());
        for (unsigned int q = 0; q < patch.points.size(); ++q)
          for (const auto &e : patch.points[q].load)
            B(index(e.cell, e.dof), q) += e.weight;
        return B;
      }

      /// g(p, q) from the solutions X of the loads: the same weights.
      template <typename Number>
      Eigen::Matrix<Number, Eigen::Dynamic, Eigen::Dynamic>
      at_points(const ContactPatch                                          &patch,
                const Eigen::Matrix<Number, Eigen::Dynamic, Eigen::Dynamic> &X) const
      {
        const unsigned int                                    P = patch.points.size();
        Eigen::Matrix<Number, Eigen::Dynamic, Eigen::Dynamic> g =
          Eigen::Matrix<Number, Eigen::Dynamic, Eigen::Dynamic>::Zero(P, X.cols());
        for (unsigned int p = 0; p < P; ++p)
          for (const auto &e : patch.points[p].load)
            g.row(p) += e.weight * X.row(index(e.cell, e.dof));
        return g;
      }
    };
  } // namespace periodic
} // namespace greentread
