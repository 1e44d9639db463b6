#include "infer/straighten.hpp"

#include <cmath>

#include <Eigen/Dense>

namespace g2d::infer {

namespace {

constexpr double kPi = 3.14159265358979323846;

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// Rows n_g · (x_to − x_from) for the edges of shared groups.
MatrixXd parallelRows(const ExampleShape& shape, const std::vector<std::size_t>& shared, const std::vector<int>& groupOf,
                      const std::vector<double>& groups, Index unknowns) {
    MatrixXd c = MatrixXd::Zero(static_cast<Index>(shared.size()), unknowns);
    for (std::size_t k = 0; k < shared.size(); ++k) {
        const ExampleEdge& e = shape.edges[shared[k]];
        const double t = groups[static_cast<std::size_t>(groupOf[shared[k]])] * kPi / 180;
        const double nx = -std::sin(t), ny = std::cos(t);
        const auto r = static_cast<Index>(k);
        c(r, 2 * e.to) += nx;
        c(r, 2 * e.to + 1) += ny;
        c(r, 2 * e.from) -= nx;
        c(r, 2 * e.from + 1) -= ny;
    }
    return c;
}

// A line's direction in [0, 180).
double lineDegrees(double dx, double dy) {
    double d = std::atan2(dy, dx) * 180 / kPi;
    if (d < 0) d += 180;
    if (d >= 180) d -= 180;
    return d;
}

}  // namespace

void straighten(const ExampleShape& shape, const std::vector<int>& groupOf, std::vector<double>& groups) {
    std::vector<int> members(groups.size(), 0);
    for (int g : groupOf) ++members[static_cast<std::size_t>(g)];
    std::vector<std::size_t> shared;   // edges of groups with several members
    for (std::size_t e = 0; e < groupOf.size(); ++e)
        if (members[static_cast<std::size_t>(groupOf[e])] > 1) shared.push_back(e);
    // A group at a whole degree is taken as drawn on purpose; the others were averaged from noise.
    std::vector<char> fixed(groups.size(), 0);
    for (std::size_t g = 0; g < groups.size(); ++g) fixed[g] = groups[g] == std::round(groups[g]) ? 1 : 0;
    const auto n = static_cast<Index>(shape.vertices.size());
    VectorXd x0(2 * n);
    for (Index v = 0; v < n; ++v) {
        x0(2 * v) = shape.vertices[static_cast<std::size_t>(v)].x;
        x0(2 * v + 1) = shape.vertices[static_cast<std::size_t>(v)].y;
    }
    VectorXd x = x0;
    if (!shared.empty()) {
        // Alternating: the drawing nearest x0 with its groups nearly parallel
        // (weight 1/mu on parallelism), then each averaged group's direction
        // from that drawing; mu shrinks, so the directions settle on a set
        // some drawing near the example has exactly.
        for (double mu : {1e-2, 1e-4, 1e-6, 1e-8}) {
            for (int round = 0; round < 8; ++round) {
                const MatrixXd c = parallelRows(shape, shared, groupOf, groups, 2 * n);
                const MatrixXd normal = c.transpose() * c + mu * MatrixXd::Identity(2 * n, 2 * n);
                x = normal.ldlt().solve(mu * x0);
                std::vector<double> sx(groups.size(), 0), sy(groups.size(), 0);   // of (cos 2a, sin 2a)·length²
                for (std::size_t e : shared) {
                    const ExampleEdge& ed = shape.edges[e];
                    const double dx = x(2 * ed.to) - x(2 * ed.from), dy = x(2 * ed.to + 1) - x(2 * ed.from + 1);
                    const double a = 2 * std::atan2(dy, dx), w = dx * dx + dy * dy;
                    sx[static_cast<std::size_t>(groupOf[e])] += w * std::cos(a);
                    sy[static_cast<std::size_t>(groupOf[e])] += w * std::sin(a);
                }
                for (std::size_t g = 0; g < groups.size(); ++g) {
                    if (fixed[g] || members[g] < 2 || (sx[g] == 0 && sy[g] == 0)) continue;
                    const double a = std::atan2(sy[g], sx[g]) / 2;
                    groups[g] = lineDegrees(std::cos(a), std::sin(a));
                }
            }
        }
        // Exactly parallel: the nearest drawing to the last one with these directions.
        const MatrixXd c = parallelRows(shape, shared, groupOf, groups, 2 * n);
        Eigen::CompleteOrthogonalDecomposition<MatrixXd> cod(c);
        x -= cod.solve(c * x);
    }
    for (std::size_t e = 0; e < groupOf.size(); ++e) {
        if (members[static_cast<std::size_t>(groupOf[e])] != 1) continue;
        const ExampleEdge& ed = shape.edges[e];
        groups[static_cast<std::size_t>(groupOf[e])] = lineDegrees(x(2 * ed.to) - x(2 * ed.from), x(2 * ed.to + 1) - x(2 * ed.from + 1));
    }
}

}  // namespace g2d::infer
