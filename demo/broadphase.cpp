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
          ny_(columns(region.upperBound.y - region.lowerBound.y, cell)),
          cells_(static_cast<size_t>(nx_) * static_cast<size_t>(ny_)) {}
    int32 add(const b2AABB &box, uintptr_t tag) override;
    void move(int32 proxy, const b2AABB &box) override;
    void remove(int32 proxy) override;
    void query(const b2AABB &box, std::vector<uintptr_t> &tags) override;

private:
    struct Range {
        int x0, y0, x1, y1;
        bool operator==(const Range &o) const { return x0 == o.x0 && y0 == o.y0 && x1 == o.x1 && y1 == o.y1; }
    };
    // A box as a cell lists it: everything a query needs, so a query reads
    // only the cells' own memory.
    struct Entry {
        b2AABB box;
        uintptr_t tag;
        int x0, y0;  // its first column and row
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
    std::vector<Entry> &cell(int x, int y) {
        return cells_[static_cast<size_t>(y) * static_cast<size_t>(nx_) + static_cast<size_t>(x)];
    }
    Entry *find(int x, int y, uintptr_t tag) {
        std::vector<Entry> &c = cell(x, y);
        return &*std::find_if(c.begin(), c.end(), [tag](const Entry &e) { return e.tag == tag; });
    }
    void list(const Entry &e, const Range &r);
    void unlist(uintptr_t tag, const Range &r);

    float x0_, y0_, inv_cell_;
    int nx_, ny_;
    std::vector<std::vector<Entry>> cells_;
    std::vector<uintptr_t> tag_;  // by proxy
    std::vector<Range> range_;    // by proxy: the cells that list it
    std::vector<int32> free_;
};

void CellGrid::list(const Entry &e, const Range &r) {
    for (int y = r.y0; y <= r.y1; ++y)
        for (int x = r.x0; x <= r.x1; ++x) cell(x, y).push_back(e);
}

void CellGrid::unlist(uintptr_t tag, const Range &r) {
    for (int y = r.y0; y <= r.y1; ++y)
        for (int x = r.x0; x <= r.x1; ++x) {
            std::vector<Entry> &c = cell(x, y);
            *find(x, y, tag) = c.back();
            c.pop_back();
        }
}

int32 CellGrid::add(const b2AABB &box, uintptr_t tag) {
    int32 proxy;
    if (free_.empty()) {
        proxy = static_cast<int32>(tag_.size());
        tag_.push_back(0);
        range_.push_back(Range{});
    } else {
        proxy = free_.back();
        free_.pop_back();
    }
    const size_t k = static_cast<size_t>(proxy);
    tag_[k] = tag;
    range_[k] = range_of(box);
    list(Entry{box, tag, range_[k].x0, range_[k].y0}, range_[k]);
    return proxy;
}

void CellGrid::move(int32 proxy, const b2AABB &box) {
    const size_t k = static_cast<size_t>(proxy);
    const Range r = range_of(box);
    if (r == range_[k]) {
        for (int y = r.y0; y <= r.y1; ++y)
            for (int x = r.x0; x <= r.x1; ++x) find(x, y, tag_[k])->box = box;
        return;
    }
    unlist(tag_[k], range_[k]);
    range_[k] = r;
    list(Entry{box, tag_[k], r.x0, r.y0}, r);
}

void CellGrid::remove(int32 proxy) {
    const size_t k = static_cast<size_t>(proxy);
    unlist(tag_[k], range_[k]);
    free_.push_back(proxy);
}

void CellGrid::query(const b2AABB &box, std::vector<uintptr_t> &tags) {
    const Range q = range_of(box);
    for (int y = q.y0; y <= q.y1; ++y)
        for (int x = q.x0; x <= q.x1; ++x)
            for (const Entry &e : cell(x, y)) {
                if (x != std::max(q.x0, e.x0) || y != std::max(q.y0, e.y0)) continue;  // reported elsewhere
                if (b2TestOverlap(e.box, box)) tags.push_back(e.tag);
            }
}

}  // namespace

std::unique_ptr<Broadphase> make_dynamic_tree() { return std::unique_ptr<Broadphase>(new DynamicTree()); }

std::unique_ptr<Broadphase> make_cell_grid(const b2AABB &region, float cell) {
    return std::unique_ptr<Broadphase>(new CellGrid(region, cell));
}

}  // namespace demo
