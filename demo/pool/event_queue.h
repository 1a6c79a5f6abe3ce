/* SPDX-License-Identifier: MIT */
// event_queue.h - the exact engine's pending events, earliest first: a
// binary heap for the events due soon, and buckets for the rest.
//
// Time is cut into buckets of a fixed width w; an event at time t belongs to
// bucket k(t) = floor(t / w).  Rounding keeps k monotone (t1 <= t2 gives
// k(t1) <= k(t2)), so an event of a later bucket is always later.  The heap
// holds exactly the events of buckets up to the current one; later ones wait
// unordered: in a ring of R buckets if due within R buckets, else in one
// overflow list, which is sorted into the ring every R/2 buckets (an event
// put there is at least R buckets ahead, so none falls due in between).
// When the heap runs dry, the next bucket's events move into it.  Pops come
// out in the same order as from one heap of everything: ties are broken by
// E's total order, and every waiting event is later than every heap event.
//
// Why: the gas keeps about two pending events a ball, most of them a few
// frames ahead; one heap of them all (100,000 balls: 200,000 events, 6 MB)
// misses the cache on nearly every level of every pop, while the heap of
// the current bucket alone stays small, and a later event costs one append.
#ifndef C2D_DEMO_EVENT_QUEUE_H
#define C2D_DEMO_EVENT_QUEUE_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace demo {

// E: has a time t (double, >= 0) and a strict total order operator>.
template <typename E>
class EventQueue {
public:
    explicit EventQueue(double width) : inv_width_(1.0 / width), ring_(kRing) {}

    void push(const E &e) {
        const int64_t k = bucket(e.t);
        if (k <= current_) {
            heap_.push_back(e);
            std::push_heap(heap_.begin(), heap_.end(), std::greater<E>());
        } else if (k < current_ + kRing) {
            ring_[slot(k)].push_back(e);
            ++in_ring_;
        } else {
            far_.push_back(e);
        }
    }

    // The earliest event, removed into e, if its time is at most t_limit.
    bool pop_until(double t_limit, E &e) {
        for (;;) {
            if (!heap_.empty()) {
                if (heap_.front().t > t_limit) return false;
                std::pop_heap(heap_.begin(), heap_.end(), std::greater<E>());
                e = heap_.back();
                heap_.pop_back();
                return true;
            }
            // every waiting event is in a bucket after the current one: after
            // t_limit once the current bucket is t_limit's
            if ((in_ring_ == 0 && far_.empty()) || current_ >= bucket(t_limit)) return false;
            advance();
        }
    }

    bool empty() const { return heap_.empty() && in_ring_ == 0 && far_.empty(); }

    void clear() {
        heap_.clear();
        for (std::vector<E> &b : ring_) b.clear();
        in_ring_ = 0;
        far_.clear();
    }

private:
    static constexpr int64_t kRing = 256;

    int64_t bucket(double t) const {
        const double k = std::floor(t * inv_width_);
        return k < 0x1p52 ? static_cast<int64_t>(k) : static_cast<int64_t>(0x1p52);  // far beyond any run
    }
    static size_t slot(int64_t k) { return static_cast<size_t>(k % kRing); }

    // The next bucket (or, with the ring empty, the first bucket with an
    // event) becomes the current one: its events go into the heap.
    void advance() {
        if (in_ring_ == 0) {
            int64_t first = bucket(far_.front().t);
            for (const E &e : far_) first = std::min(first, bucket(e.t));
            current_ = std::max(current_, first - 1);
            refill();
        }
        ++current_;
        if (current_ % (kRing / 2) == 0) refill();
        std::vector<E> &due = ring_[slot(current_)];
        in_ring_ -= static_cast<int64_t>(due.size());
        for (const E &e : due) heap_.push_back(e);
        due.clear();
        std::make_heap(heap_.begin(), heap_.end(), std::greater<E>());
    }

    // Overflow events now within the ring's reach move into it.
    void refill() {
        size_t kept = 0;
        for (const E &e : far_) {
            const int64_t k = bucket(e.t);
            if (k < current_ + kRing) {
                ring_[slot(k)].push_back(e);
                ++in_ring_;
            } else {
                far_[kept++] = e;
            }
        }
        far_.resize(kept);
    }

    double inv_width_;
    int64_t current_ = 0;
    std::vector<E> heap_;
    std::vector<std::vector<E>> ring_;
    int64_t in_ring_ = 0;
    std::vector<E> far_;
};

}  // namespace demo

#endif
