// broadphase.cpp - see broadphase.h.  The grid reports a box found in
// several cells once: only in the first cell (lowest column, then lowest
// row) that both it and the query cover, the cell at (max of the two first
// columns, max of the two first rows); overlapping boxes share that cell,
// since their column and row ranges intersect.  A cell's ranges come from
// one monotone function of the coordinate (clamped to the grid), so two
// boxes that overlap always have intersecting ranges.
#include "broadphase.h"

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
        : x0_(region.lowerBound.x), y0_(region.lowerBound.y), inv_cell_(1.0f / cell),
          nx_(columns(region.upperBound.x - region.lowerBound.x, cell)),
          ny_(columns(region.upperBound.y - region.lowerBound.y, cell)), cells_(static_cast<size_t>(nx_ * ny_)) {}
    int32 add(const b2AABB &box, uintptr_t tag) override;
    void move(int32 proxy, const b2AABB &box) override;
    void remove(int32 proxy) override;
    void query(const b2AABB &box, std::vector<uintptr_t> &tags) override;

private:
    struct Range {
        int x0, y0, x1, y1;
        bool operator==(const Range &o) const { return x0 == o.x0 && y0 == o.y0 && x1 == o.x1 && y1 == o.y1; }
    };
    struct Proxy {
        b2AABB box;
        uintptr_t tag;
        Range cells;
    };
    static int columns(float extent, float cell) { return std::max(1, static_cast<int>(std::ceil(extent / cell))); }
    int index(float v, float origin, int n) const {
        const float k = std::floor((v - origin) * inv_cell_);
        return k < 0 ? 0 : k >= static_cast<float>(n - 1) ? n - 1 : static_cast<int>(k);
    }
    Range range_of(const b2AABB &b) const {
        return Range{index(b.lowerBound.x, x0_, nx_), index(b.lowerBound.y, y0_, ny_), index(b.upperBound.x, x0_, nx_),
                     index(b.upperBound.y, y0_, ny_)};
    }
    std::vector<int32> &cell(int x, int y) { return cells_[static_cast<size_t>(y) * static_cast<size_t>(nx_) + static_cast<size_t>(x)]; }
    void list(int32 proxy, const Range &r);
    void unlist(int32 proxy, const Range &r);

    float x0_, y0_, inv_cell_;
    int nx_, ny_;
    std::vector<std::vector<int32>> cells_;
    std::vector<Proxy> proxies_;
    std::vector<int32> free_;
};

void CellGrid::list(int32 proxy, const Range &r) {
    for (int y = r.y0; y <= r.y1; ++y)
        for (int x = r.x0; x <= r.x1; ++x) cell(x, y).push_back(proxy);
}

void CellGrid::unlist(int32 proxy, const Range &r) {
    for (int y = r.y0; y <= r.y1; ++y)
        for (int x = r.x0; x <= r.x1; ++x) {
            std::vector<int32> &c = cell(x, y);
            *std::find(c.begin(), c.end(), proxy) = c.back();
            c.pop_back();
        }
}

int32 CellGrid::add(const b2AABB &box, uintptr_t tag) {
    int32 proxy;
    if (free_.empty()) {
        proxy = static_cast<int32>(proxies_.size());
        proxies_.push_back(Proxy{});
    } else {
        proxy = free_.back();
        free_.pop_back();
    }
    Proxy &p = proxies_[static_cast<size_t>(proxy)];
    p = Proxy{box, tag, range_of(box)};
    list(proxy, p.cells);
    return proxy;
}

void CellGrid::move(int32 proxy, const b2AABB &box) {
    Proxy &p = proxies_[static_cast<size_t>(proxy)];
    p.box = box;
    const Range r = range_of(box);
    if (r == p.cells) return;
    unlist(proxy, p.cells);
    p.cells = r;
    list(proxy, r);
}

void CellGrid::remove(int32 proxy) {
    unlist(proxy, proxies_[static_cast<size_t>(proxy)].cells);
    free_.push_back(proxy);
}

void CellGrid::query(const b2AABB &box, std::vector<uintptr_t> &tags) {
    const Range q = range_of(box);
    for (int y = q.y0; y <= q.y1; ++y)
        for (int x = q.x0; x <= q.x1; ++x)
            for (int32 proxy : cell(x, y)) {
                const Proxy &p = proxies_[static_cast<size_t>(proxy)];
                if (x != std::max(q.x0, p.cells.x0) || y != std::max(q.y0, p.cells.y0)) continue;  // reported elsewhere
                if (b2TestOverlap(p.box, box)) tags.push_back(p.tag);
            }
}

}  // namespace

std::unique_ptr<Broadphase> make_dynamic_tree() { return std::unique_ptr<Broadphase>(new DynamicTree()); }

std::unique_ptr<Broadphase> make_cell_grid(const b2AABB &region, float cell) {
    return std::unique_ptr<Broadphase>(new CellGrid(region, cell));
}

}  // namespace demo
