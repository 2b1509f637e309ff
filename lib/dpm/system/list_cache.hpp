// A pair list kept between energy evaluations of a system, in 2D (ContactList, contact_list.hpp) and 3D
// (VertexPairList3d, vertex_pairs3d.hpp).
//
// Why in the system: every energy, force, Hessian, stress and contact count is a function of
// (const System&, x), called from relaxations, mode analyses, finite differences and scenes alike; the
// list is a cache of their pair search, not physics state, and the results do not depend on it (each list's
// header says why). So it lives in the system as a mutable cache rather than as a parameter threaded
// through every caller. Thread safety: a built list is immutable and shared (copies of a system share it
// until one needs a new list); the mutex guards only the swap, so concurrent evaluations of one system are
// safe (each keeps the list it got for the whole evaluation).
//
// List must be constructible as List(system, x) and answer valid_for(system, x): whether it still holds
// every pair the evaluation at x needs.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <mutex>

namespace softgrain::dpm {

template <class List, class System>
class ListCache
{
  public:
    ListCache() = default;
    ListCache(const ListCache& other) : list_(other.current()) {}
    ListCache& operator=(const ListCache& other)
    {
        if (this != &other) {
            std::shared_ptr<const List> list = other.current();
            const std::lock_guard lock(mutex_);
            list_ = std::move(list);
        }
        return *this;
    }

    // The list valid at x, rebuilt if the cached one is not.
    std::shared_ptr<const List> list(const System& system, const Eigen::VectorXd& x) const
    {
        std::shared_ptr<const List> cached = current();
        if (cached && cached->valid_for(system, x)) return cached;
        auto fresh = std::make_shared<const List>(system, x);
        const std::lock_guard lock(mutex_);
        list_ = fresh;
        ++builds_;
        return fresh;
    }
    // How many lists this cache object has built (a copy starts from 0): for tests of the rebuild rule.
    long builds() const
    {
        const std::lock_guard lock(mutex_);
        return builds_;
    }

  private:
    std::shared_ptr<const List> current() const
    {
        const std::lock_guard lock(mutex_);
        return list_;
    }

    mutable std::mutex mutex_;
    mutable std::shared_ptr<const List> list_;
    mutable long builds_ = 0;
};

} // namespace softgrain::dpm
