#include "infer/straighten.hpp"

#include <cmath>

#include <Eigen/Dense>

namespace g2d::infer {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

void straightenSingletons(const ExampleShape& shape, const std::vector<int>& groupOf, std::vector<double>& groups) {
    std::vector<int> members(groups.size(), 0);
    for (int g : groupOf) ++members[static_cast<std::size_t>(g)];
    std::vector<std::size_t> shared;   // edges of groups with several members
    for (std::size_t e = 0; e < groupOf.size(); ++e)
        if (members[static_cast<std::size_t>(groupOf[e])] > 1) shared.push_back(e);
    const auto n = static_cast<Eigen::Index>(shape.vertices.size());
    Eigen::VectorXd x0(2 * n);
    for (Eigen::Index v = 0; v < n; ++v) {
        x0(2 * v) = shape.vertices[static_cast<std::size_t>(v)].x;
        x0(2 * v + 1) = shape.vertices[static_cast<std::size_t>(v)].y;
    }
    Eigen::VectorXd x = x0;
    if (!shared.empty()) {
        // n · (x_to − x_from) = 0, n the group direction's normal; x = x0 − C⁺ C x0.
        Eigen::MatrixXd c = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(shared.size()), 2 * n);
        for (std::size_t k = 0; k < shared.size(); ++k) {
            const ExampleEdge& e = shape.edges[shared[k]];
            const double t = groups[static_cast<std::size_t>(groupOf[shared[k]])] * kPi / 180;
            const double nx = -std::sin(t), ny = std::cos(t);
            const auto r = static_cast<Eigen::Index>(k);
            c(r, 2 * e.to) += nx;
            c(r, 2 * e.to + 1) += ny;
            c(r, 2 * e.from) -= nx;
            c(r, 2 * e.from + 1) -= ny;
        }
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(c);
        x -= cod.solve(c * x0);
    }
    for (std::size_t e = 0; e < groupOf.size(); ++e) {
        if (members[static_cast<std::size_t>(groupOf[e])] != 1) continue;
        const ExampleEdge& ed = shape.edges[e];
        const double dx = x(2 * ed.to) - x(2 * ed.from), dy = x(2 * ed.to + 1) - x(2 * ed.from + 1);
        double d = std::atan2(dy, dx) * 180 / kPi;   // as a line, in [0, 180)
        if (d < 0) d += 180;
        if (d >= 180) d -= 180;
        groups[static_cast<std::size_t>(groupOf[e])] = d;
    }
}

}  // namespace g2d::infer
