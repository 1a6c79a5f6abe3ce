/* SPDX-License-Identifier: MIT */
// broadphase.cpp - see broadphase.h.  The grid lists a box no wider or
// taller than a cell in one cell, the one that holds its lower-left corner,
// and the few larger boxes (the gas box's walls, a ball swept unusually far)
// in one list of their own.  A query for box Q looks at the cells whose
// corners can belong to a box that overlaps Q, [Q.lower - cell, Q.upper],
// and at the large boxes: every candidate once.  A box's cell comes from
// one monotone function of the coordinate (clamped to the grid), so a box
// beyond the grid is still found.  Moving a box within its cell rewrites
// it in place; a box that changes cells swaps out of the old one.
#include "pool/broadphase.h"

#include <algorithm>
#include <cmath>

namespace demo {

namespace {

// b2DynamicTree 2.4.1 carries a void * per proxy; ours is a small integer
// that round-trips exactly and is never dereferenced.
void *as_pointer(uintptr_t tag) { return reinterpret_cast<void *>(tag); }  // NOLINT(performance-no-int-to-ptr)

class DynamicTree : public Broadphase {
public:
    int32 add(const b2AABB &box, uintptr_t tag) override { return tree_.CreateProxy(box, as_pointer(tag)); }
    // no displacement hint: the engine's boxes already span the motion, and
    // Box2D would stretch them by four times the hint, making every query slower
    void move(int32 proxy, const b2AABB &box) override { tree_.MoveProxy(proxy, box, b2Vec2(0, 0)); }
    void remove(int32 proxy) override { tree_.DestroyProxy(proxy); }
    void query(const b2AABB &box, std::vector<uintptr_t> &tags) override {
        tags_ = &tags;
        tree_.Query(this, box);
    }
    bool QueryCallback(int32 proxy) {
        tags_->push_back(reinterpret_cast<uintptr_t>(tree_.GetUserData(proxy)));
        return true;
    }

private:
    b2DynamicTree tree_;
    std::vector<uintptr_t> *tags_ = nullptr;
};

class CellGrid : public Broadphase {
public:
    CellGrid(const b2AABB &region, float cell)
        : x0_(region.lowerBound.x), y0_(region.lowerBound.y), cell_(cell), inv_cell_(1.0f / cell),
          nx_(columns(region.upperBound.x - region.lowerBound.x, cell)),
          ny_(columns(region.upperBound.y - region.lowerBound.y, cell)),
          cells_(static_cast<size_t>(nx_) * static_cast<size_t>(ny_) + 1) {}
    int32 add(const b2AABB &box, uintptr_t tag) override;
    void move(int32 proxy, const b2AABB &box) override;
    void remove(int32 proxy) override;
    void query(const b2AABB &box, std::vector<uintptr_t> &tags) override;

private:
    struct Entry {
        b2AABB box;
        uintptr_t tag;
        int32 proxy;
    };
    struct Place {
        size_t list, index;  // cells_[list][index]
    };
    static int columns(float extent, float cell) { return std::max(1, static_cast<int>(std::ceil(extent / cell))); }
    int index(float v, float origin, int n) const {
        const float k = std::floor((v - origin) * inv_cell_);
        return k < 0 ? 0 : k >= static_cast<float>(n - 1) ? n - 1 : static_cast<int>(k);
    }
    size_t large() const { return cells_.size() - 1; }
    // The list a box goes in: its lower corner's cell, or the large boxes'.
    size_t list_of(const b2AABB &b) const {
        if (b.upperBound.x - b.lowerBound.x > cell_ || b.upperBound.y - b.lowerBound.y > cell_) return large();
        return static_cast<size_t>(index(b.lowerBound.y, y0_, ny_)) * static_cast<size_t>(nx_) +
               static_cast<size_t>(index(b.lowerBound.x, x0_, nx_));
    }
    void put(int32 proxy, const b2AABB &box, uintptr_t tag);
    void take(int32 proxy);
    void scan(const std::vector<Entry> &list, const b2AABB &box, std::vector<uintptr_t> &tags) const {
        for (const Entry &e : list)
            if (b2TestOverlap(e.box, box)) tags.push_back(e.tag);
    }

    float x0_, y0_, cell_, inv_cell_;
    int nx_, ny_;
    std::vector<std::vector<Entry>> cells_;  // the cells, row by row, then the large boxes
    std::vector<Place> place_;               // by proxy
    std::vector<int32> free_;
};

void CellGrid::put(int32 proxy, const b2AABB &box, uintptr_t tag) {
    const size_t list = list_of(box);
    place_[static_cast<size_t>(proxy)] = Place{list, cells_[list].size()};
    cells_[list].push_back(Entry{box, tag, proxy});
}

// Out of its list: the list's last entry takes its place.
void CellGrid::take(int32 proxy) {
    const Place p = place_[static_cast<size_t>(proxy)];
    std::vector<Entry> &list = cells_[p.list];
    list[p.index] = list.back();
    place_[static_cast<size_t>(list[p.index].proxy)].index = p.index;
    list.pop_back();
}

int32 CellGrid::add(const b2AABB &box, uintptr_t tag) {
    int32 proxy;
    if (free_.empty()) {
        proxy = static_cast<int32>(place_.size());
        place_.push_back(Place{});
    } else {
        proxy = free_.back();
        free_.pop_back();
    }
    put(proxy, box, tag);
    return proxy;
}

void CellGrid::move(int32 proxy, const b2AABB &box) {
    const Place p = place_[static_cast<size_t>(proxy)];
    Entry &e = cells_[p.list][p.index];
    if (list_of(box) == p.list) {
        e.box = box;
        return;
    }
    const uintptr_t tag = e.tag;
    take(proxy);
    put(proxy, box, tag);
}

void CellGrid::remove(int32 proxy) {
    take(proxy);
    free_.push_back(proxy);
}

// A small box that overlaps the query has its lower corner at most one cell
// width below and left of the query's lower corner, and not beyond its
// upper corner: those cells hold every candidate, each once.
void CellGrid::query(const b2AABB &box, std::vector<uintptr_t> &tags) {
    const int x0 = index(box.lowerBound.x - cell_, x0_, nx_), x1 = index(box.upperBound.x, x0_, nx_);
    const int y0 = index(box.lowerBound.y - cell_, y0_, ny_), y1 = index(box.upperBound.y, y0_, ny_);
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
            scan(cells_[static_cast<size_t>(y) * static_cast<size_t>(nx_) + static_cast<size_t>(x)], box, tags);
    scan(cells_[large()], box, tags);
}

}  // namespace

std::unique_ptr<Broadphase> make_dynamic_tree() { return std::unique_ptr<Broadphase>(new DynamicTree()); }

std::unique_ptr<Broadphase> make_cell_grid(const b2AABB &region, float cell) {
    return std::unique_ptr<Broadphase>(new CellGrid(region, cell));
}

}  // namespace demo
