#pragma once
// Appends moves to a toolpath and adds up its feed and rapid travel. Moves that go nowhere are
// dropped.
#include <aeronc/toolpath/Toolpath.h>

namespace aeronc::toolpath {

class MoveWriter {
public:
    explicit MoveWriter(Toolpath& path) : path_(path) {}

    void rapid(double u, double v, double h) { add(Move::Kind::Rapid, u, v, h); }
    void feed(double u, double v, double h) { add(Move::Kind::Feed, u, v, h); }
    void plunge(double u, double v, double h) { add(Move::Kind::Plunge, u, v, h); }
    void feed(const Point& p, double h) { feed(p[0], p[1], h); }
    // A canned cycle from `clearance` (where the tool stands over the hole): down to r at rapid,
    // to `bottom` at feed (pecking by q), back to r at rapid. The tool ends at r.
    void drill(double u, double v, double bottom, double r, double q, double dwell);

    // Up to `clearance` if below it, across to (u, v) and down to h, all at rapid.
    void rapidOver(const Point& p, double clearance, double h);
    // Up to h from wherever the tool is, at rapid.
    void retract(double h);

    bool started() const { return started_; }
    double u() const { return u_; }
    double v() const { return v_; }
    double h() const { return h_; }

private:
    void add(Move::Kind kind, double u, double v, double h);

    Toolpath& path_;
    bool started_ = false;
    double u_ = 0, v_ = 0, h_ = 0;
};

}  // namespace aeronc::toolpath
