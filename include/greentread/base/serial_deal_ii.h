#pragma once

#include <deal.II/base/multithread_info.h>

/**
 * @file
 * deal.II on one thread for a scope: the finite-element set-up (meshes,
 * FEValues, assembly) runs there, so that its round-off does not depend on
 * the thread count. With two threads, deal.II's own tasks in that set-up
 * gave Jacobians that differed in the last bits from run to run (measured:
 * a section cell's sum of JxW, 0.0012239999999964076 against
 * 0.0012239999999971148), and every stage after it inherited the
 * difference. GreenTread's own threads (base::for_each_index(),
 * base::run_on_threads()) read dealii::MultithreadInfo::n_threads(): the
 * limit is restored when the scope ends, before they start.
 */

namespace greentread
{
  namespace base
  {
    /// While it lives, dealii::MultithreadInfo::n_threads() is 1.
    class SerialDealII
    {
    public:
      SerialDealII()
          : saved(dealii::MultithreadInfo::n_threads())
      {
        dealii::MultithreadInfo::set_thread_limit(1);
      }

      ~SerialDealII()
      {
        dealii::MultithreadInfo::set_thread_limit(saved);
      }

      SerialDealII(const SerialDealII &) = delete;
      SerialDealII &
      operator=(const SerialDealII &) = delete;

    private:
      unsigned int saved;
    };
  } // namespace base
} // namespace greentread
