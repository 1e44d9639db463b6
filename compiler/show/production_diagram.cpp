#include "show/production_diagram.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "g2d/svg_writer.hpp"
#include "g2d/value.hpp"
#include "sema/const_fold.hpp"

namespace g2d::show {

namespace {

using rt::xmlEscape;

constexpr double kPanel = 180;      // a graph's box, in px
constexpr double kGap = 60;         // between boxes (room for the arrow)
constexpr double kNodeRadius = 7;
const char* const kKept = "#ff8c00";
const char* const kNew = "#1a9e3a";
const char* const kDeleted = "#d62728";
const char* const kNegative = "#999999";

std::string num(double x) { return rt::formatNumber(std::round(x * 100) / 100); }

// The source text of a span (one line, or the first line of several).
std::string sourceText(const SourceManager& sm, const Span& s) {
    if (!s.valid()) return "";
    const std::string line = sm.lineText(s.file, s.line);
    const std::size_t begin = s.col > 0 ? s.col - 1 : 0;
    const std::size_t end = s.endLine == s.line && s.endCol > s.col ? s.endCol - 1 : line.size();
    // Columns count code points; the texts shown are almost always ASCII.
    return begin < line.size() ? line.substr(begin, end - begin) : "";
}

struct DrawNode {
    std::string label;
    double x = 0, y = 0;          // graph units, y up
    const char* color = "#444444";
    bool dashed = false;
};
struct DrawEdge {
    int a = 0, b = 0;
    std::string label;
    bool directed = false;
    const char* color = "#444444";
    bool dashed = false;
};
struct DrawFace {
    std::vector<int> corners;     // indices into the panel's nodes
    std::string label;
    const char* stroke = "#9a86c0";
    bool dashed = false;
};
struct Panel {
    std::string caption;
    std::vector<DrawNode> nodes;
    std::vector<DrawEdge> edges;
    std::vector<DrawFace> faces;
};

// Evenly on a circle (one node in the middle, two side by side).
void circleLayout(std::vector<DrawNode>& nodes, std::size_t from, double radius) {
    const std::size_t n = nodes.size() - from;
    for (std::size_t i = 0; i < n; ++i) {
        const double angle = n == 2 ? M_PI * static_cast<double>(i) : M_PI / 2 + 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
        nodes[from + i].x = n == 1 ? 0 : radius * std::cos(angle);
        nodes[from + i].y = n == 1 ? 0 : radius * std::sin(angle);
    }
}

std::string kindName(const ir::Program& prog, int kind) { return kind < 0 ? "*" : prog.kinds[static_cast<std::size_t>(kind)].name; }
// A face of any corner count, drawn as the node its match is pinned to (its first corner).
std::string faceLabel(const ir::Program& prog, const ir::PatternFace& f) {
    return (f.name.empty() ? "" : f.name + ": ") + kindName(prog, f.kind) + " (any corners)";
}
bool directed(const ir::Program& prog, int kind) { return kind >= 0 && prog.kinds[static_cast<std::size_t>(kind)].directed; }

std::string drawPanel(const Panel& p, double left, double top) {
    std::string out = "<g transform=\"translate(" + num(left) + " " + num(top) + ")\">\n";
    out += "<rect width=\"" + num(kPanel) + "\" height=\"" + num(kPanel) + "\" fill=\"white\" stroke=\"#cccccc\"/>\n";
    out += "<text x=\"" + num(kPanel / 2) + "\" y=\"-6\" text-anchor=\"middle\" font-size=\"12\">" + xmlEscape(p.caption) + "</text>\n";
    // Fit the graph into the box, y up.
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    for (std::size_t i = 0; i < p.nodes.size(); ++i) {
        const auto& n = p.nodes[i];
        x0 = i ? std::min(x0, n.x) : n.x; x1 = i ? std::max(x1, n.x) : n.x;
        y0 = i ? std::min(y0, n.y) : n.y; y1 = i ? std::max(y1, n.y) : n.y;
    }
    const double span = std::max({x1 - x0, y1 - y0, 1e-9});
    const double scale = p.nodes.size() > 1 ? (kPanel - 60) / span : 1;
    auto sx = [&](double x) { return kPanel / 2 + (x - (x0 + x1) / 2) * scale; };
    auto sy = [&](double y) { return kPanel / 2 - (y - (y0 + y1) / 2) * scale; };
    for (const auto& f : p.faces) {   // below the edges, labelled at the corners' mean
        std::string points;
        double cx = 0, cy = 0;
        for (int c : f.corners) {
            const auto& n = p.nodes[static_cast<std::size_t>(c)];
            points += (points.empty() ? "" : " ") + num(sx(n.x)) + "," + num(sy(n.y));
            cx += sx(n.x) / static_cast<double>(f.corners.size());
            cy += sy(n.y) / static_cast<double>(f.corners.size());
        }
        out += "<polygon points=\"" + points + "\" fill=\"#e8e0f4\" stroke=\"" + std::string(f.stroke) + "\" stroke-width=\"1\"" +
               (f.dashed ? " stroke-dasharray=\"4 3\"" : "") + "/>\n";
        out += "<text x=\"" + num(cx) + "\" y=\"" + num(cy) + "\" text-anchor=\"middle\" font-size=\"9\" fill=\"#6a5890\">" +
               xmlEscape(f.label) + "</text>\n";
    }
    for (const auto& e : p.edges) {
        const auto& a = p.nodes[static_cast<std::size_t>(e.a)];
        const auto& b = p.nodes[static_cast<std::size_t>(e.b)];
        double ax = sx(a.x), ay = sy(a.y), bx = sx(b.x), by = sy(b.y);
        const double len = std::hypot(bx - ax, by - ay);
        if (len > 2 * kNodeRadius) {   // stop at the circles
            const double ux = (bx - ax) / len, uy = (by - ay) / len;
            ax += ux * kNodeRadius; ay += uy * kNodeRadius; bx -= ux * kNodeRadius; by -= uy * kNodeRadius;
        }
        out += "<line x1=\"" + num(ax) + "\" y1=\"" + num(ay) + "\" x2=\"" + num(bx) + "\" y2=\"" + num(by) + "\" stroke=\"" +
               e.color + "\" stroke-width=\"2\"" + (e.dashed ? " stroke-dasharray=\"5 3\"" : "") +
               (e.directed ? " marker-end=\"url(#show-arrow)\"" : "") + "/>\n";
        out += "<text x=\"" + num((ax + bx) / 2) + "\" y=\"" + num((ay + by) / 2 - 4) +
               "\" text-anchor=\"middle\" font-size=\"9\" fill=\"#555555\">" + xmlEscape(e.label) + "</text>\n";
    }
    for (const auto& n : p.nodes) {
        out += "<circle cx=\"" + num(sx(n.x)) + "\" cy=\"" + num(sy(n.y)) + "\" r=\"" + num(kNodeRadius) + "\" fill=\"" + n.color +
               "\" fill-opacity=\"0.25\" stroke=\"" + n.color + "\" stroke-width=\"2\"" + (n.dashed ? " stroke-dasharray=\"4 2\"" : "") + "/>\n";
        out += "<text x=\"" + num(sx(n.x)) + "\" y=\"" + num(sy(n.y) + kNodeRadius + 11) +
               "\" text-anchor=\"middle\" font-size=\"10\">" + xmlEscape(n.label) + "</text>\n";
    }
    return out + "</g>\n";
}

Panel axiomPanel(const ir::Program& prog) {
    Panel p;
    p.caption = "axiom";
    bool placed = true;
    for (const auto& n : prog.axiom.nodes) {
        DrawNode d;
        d.label = n.name + ": " + kindName(prog, n.kind);
        if (n.position) {
            const auto v = sema::fold(*n.position, prog);
            if (v && std::holds_alternative<ir::Vec2>(*v)) {
                d.x = std::get<ir::Vec2>(*v).x;
                d.y = std::get<ir::Vec2>(*v).y;
            } else {
                placed = false;
            }
        }
        p.nodes.push_back(d);
    }
    if (!placed) circleLayout(p.nodes, 0, 1);
    for (const auto& e : prog.axiom.edges)
        p.edges.push_back(DrawEdge{e.src, e.dst, kindName(prog, e.kind), directed(prog, e.kind)});
    for (const auto& f : prog.axiom.faces)
        p.faces.push_back(DrawFace{f.corners, (f.name.empty() ? "" : f.name + ": ") + kindName(prog, f.kind)});
    return p;
}

// The mother graph: its own nodes, then each negative condition's.
// (An element kept by any daughter is drawn kept; one no daughter keeps, deleted.)
Panel motherPanel(const ir::Program& prog, const ir::Rule& r, const std::vector<bool>& keptAnywhere) {
    Panel p;
    p.caption = "mother";
    bool sketched = !r.nodes.empty();
    for (std::size_t i = 0; i < r.nodes.size(); ++i) {
        const auto& n = r.nodes[i];
        DrawNode d;
        d.label = n.anchorOf >= 0 ? faceLabel(prog, r.faces[static_cast<std::size_t>(n.anchorOf)]) : n.name + ": " + kindName(prog, n.kind);
        d.color = keptAnywhere[i] ? kKept : kDeleted;
        d.dashed = !keptAnywhere[i];
        if (n.sketch) { d.x = n.sketch->x; d.y = n.sketch->y; } else sketched = false;
        p.nodes.push_back(d);
    }
    if (!sketched) circleLayout(p.nodes, 0, 1);
    for (std::size_t i = 0; i < r.edges.size(); ++i) {
        const auto& e = r.edges[i];
        bool kept = false;
        for (const auto& d : r.daughters)
            for (const auto& de : d.edges) kept = kept || de.motherEdge == static_cast<int>(i);
        p.edges.push_back(DrawEdge{e.src, e.dst, (e.name.empty() ? "" : e.name + ": ") + kindName(prog, e.kind), directed(prog, e.kind),
                                   kept ? kKept : kDeleted, !kept});
    }
    for (std::size_t i = 0; i < r.faces.size(); ++i) {
        const auto& f = r.faces[i];
        if (f.corners.empty()) continue;   // drawn as its anchor node
        bool kept = false;
        for (const auto& d : r.daughters)
            for (const auto& k : d.keptFaces) kept = kept || k.motherFace == static_cast<int>(i);
        p.faces.push_back(DrawFace{f.corners, f.name + ": " + kindName(prog, f.kind), kept ? kKept : kDeleted, !kept});
    }
    for (const auto& nac : r.nacs) {
        const std::size_t first = p.nodes.size();
        for (const auto& n : nac.nodes) {
            const std::string label = n.anchorOf >= 0 ? faceLabel(prog, nac.faces[static_cast<std::size_t>(n.anchorOf - nac.outerFaces)])
                                                      : n.name + ": " + kindName(prog, n.kind);
            p.nodes.push_back(DrawNode{"not " + label, 0, 0, kNegative, true});
        }
        circleLayout(p.nodes, first, 1.8);
        for (std::size_t i = first; i < p.nodes.size(); ++i) p.nodes[i].y -= 0.4;   // off the mother's circle
        for (const auto& e : nac.edges)
            p.edges.push_back(DrawEdge{e.src, e.dst, "not " + kindName(prog, e.kind), directed(prog, e.kind), kNegative, true});
        for (const auto& f : nac.faces)
            if (!f.corners.empty())
                p.faces.push_back(DrawFace{f.corners, "not " + (f.name.empty() ? "" : f.name + ": ") + kindName(prog, f.kind), kNegative, true});
    }
    return p;
}

Panel daughterPanel(const ir::Program& prog, const ir::Rule& r, const ir::Daughter& d, const Panel& mother, const std::string& caption) {
    Panel p;
    p.caption = caption;
    std::vector<bool> placed;
    for (const auto& n : d.nodes) {
        DrawNode dn;
        dn.label = n.name + ": " + kindName(prog, n.kind >= 0 ? n.kind : (n.motherNode >= 0 ? r.nodes[static_cast<std::size_t>(n.motherNode)].kind : -1));
        if (n.motherNode >= 0 && r.nodes[static_cast<std::size_t>(n.motherNode)].anchorOf >= 0) {
            const int face = r.nodes[static_cast<std::size_t>(n.motherNode)].anchorOf;
            const bool kept = std::any_of(d.keptFaces.begin(), d.keptFaces.end(), [&](const ir::KeptFace& k) { return k.motherFace == face; });
            dn.label = kept ? faceLabel(prog, r.faces[static_cast<std::size_t>(face)]) : "(a deleted face's first corner)";
        }
        const bool kept = n.motherNode >= 0;
        dn.color = kept ? kKept : kNew;
        if (kept) {   // a kept node keeps its place, so the mapping reads across
            dn.x = mother.nodes[static_cast<std::size_t>(n.motherNode)].x;
            dn.y = mother.nodes[static_cast<std::size_t>(n.motherNode)].y;
        } else if (n.sketch) {
            dn.x = n.sketch->x;
            dn.y = n.sketch->y;
        }
        placed.push_back(kept || n.sketch.has_value());
        p.nodes.push_back(dn);
    }
    // New nodes without a sketch: on a row below the kept ones, in the order
    // of their kept neighbours' x (fewer crossings).
    double minX = 0, maxX = 0, minY = 0;
    bool any = false;
    for (std::size_t i = 0; i < p.nodes.size(); ++i) {
        if (!placed[i]) continue;
        minX = any ? std::min(minX, p.nodes[i].x) : p.nodes[i].x;
        maxX = any ? std::max(maxX, p.nodes[i].x) : p.nodes[i].x;
        minY = any ? std::min(minY, p.nodes[i].y) : p.nodes[i].y;
        any = true;
    }
    std::vector<std::pair<double, std::size_t>> row;
    for (std::size_t i = 0; i < p.nodes.size(); ++i) {
        if (placed[i]) continue;
        double sum = 0;
        int count = 0;
        for (const auto& e : d.edges) {
            const int other = e.src == static_cast<int>(i) ? e.dst : e.dst == static_cast<int>(i) ? e.src : -1;
            if (other >= 0 && placed[static_cast<std::size_t>(other)]) {
                sum += p.nodes[static_cast<std::size_t>(other)].x;
                ++count;
            }
        }
        row.emplace_back(count ? sum / count : (minX + maxX) / 2, i);
    }
    std::stable_sort(row.begin(), row.end());
    const double rowWidth = std::max(maxX - minX, 1.0);
    for (std::size_t k = 0; k < row.size(); ++k) {
        auto& n = p.nodes[row[k].second];
        n.x = row.size() == 1 ? (minX + maxX) / 2 : minX + rowWidth * static_cast<double>(k) / static_cast<double>(row.size() - 1);
        n.y = (any ? minY : 0) - 0.8 * rowWidth;
    }
    for (const auto& e : d.edges)
        p.edges.push_back(DrawEdge{e.src, e.dst, (e.name.empty() ? "" : e.name + ": ") + kindName(prog, e.kind), directed(prog, e.kind),
                                   e.motherEdge >= 0 ? kKept : kNew});
    for (const auto& f : d.faces) {
        if (std::find(f.corners.begin(), f.corners.end(), -1) != f.corners.end()) continue;
        p.faces.push_back(DrawFace{f.corners, (f.name.empty() ? "" : f.name + ": ") + kindName(prog, f.kind), kNew});
    }
    for (const auto& k : d.keptFaces) {   // on the daughter nodes keeping its corners
        const auto& mf = r.faces[static_cast<std::size_t>(k.motherFace)];
        std::vector<int> corners;
        for (int c : mf.corners)
            for (std::size_t i = 0; i < d.nodes.size(); ++i)
                if (d.nodes[i].motherNode == c) corners.push_back(static_cast<int>(i));
        if (!mf.corners.empty() && corners.size() == mf.corners.size()) p.faces.push_back(DrawFace{corners, mf.name + ": " + kindName(prog, mf.kind), kKept});
    }
    // A loop's elements exist only per turn: said in words.
    for (const auto& l : d.loops) {
        const auto& f = r.faces[static_cast<std::size_t>(l.motherFace)];
        auto count = [](std::size_t n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); };
        p.caption += std::string(" · for each ") + (l.sides ? "side" : "corner") + " of " + f.name + ": " + count(l.nodes.size(), "node") +
                     ", " + count(l.edges.size(), "edge") + ", " + count(l.faces.size(), "face");
    }
    for (const auto& rf : d.ringFaces)
        p.caption += " · a " + kindName(prog, rf.kind) + " over every turn's node" + (rf.reversed ? ", reversed" : "");
    for (const auto& sp : d.splits)
        p.caption += " · split " + r.faces[static_cast<std::size_t>(sp.motherFace)].name +
                     (sp.centre ? " around a new " + kindName(prog, sp.centre->kind) : std::string(" by a chord")) + ", edges " +
                     kindName(prog, sp.edgeKind) + (sp.cond ? " from the chosen corners" : " from every corner");
    return p;
}

// The rule's options, with those its priority gives it (`priority P limit N
// parallel;`): what decides when and how often it applies.
// A compound's heading: its name and what it runs, in order.
// Entries [from, to) of a list, a repeat's as `repeat { … }`.
static std::string listText(const std::vector<ir::SequenceEntry>& list, std::size_t from, std::size_t to, const ir::Program& prog) {
    std::string out;
    for (std::size_t i = from; i < to; ++i) {
        const auto& e = list[i];
        out += out.empty() ? "" : "; ";
        if (e.kind == ir::SequenceEntry::Kind::Repeat) {
            const std::size_t body = static_cast<std::size_t>(e.body);
            out += "repeat { " + listText(list, i + 1, i + 1 + body, prog) + " }";
            i += body;
        } else {
            out += e.kind == ir::SequenceEntry::Kind::Compound ? prog.compounds[static_cast<std::size_t>(e.index)].name
                                                               : prog.rules[static_cast<std::size_t>(e.index)].name;
        }
    }
    return out;
}

std::string compoundHeading(const ir::Compound& c, const ir::Program& prog) {
    return "compound " + c.name + " · runs " + listText(c.entries, 0, c.entries.size(), prog) + " within each match's scope";
}

std::string ruleHeading(const ir::Rule& r, const ir::Program& prog, const SourceManager& sources) {
    if (r.compound >= 0) return compoundHeading(prog.compounds[static_cast<std::size_t>(r.compound)], prog);
    std::string h = "rule " + r.name;
    const auto prio = prog.priorities.find(r.priority);
    const ir::PriorityConfig* config = prio != prog.priorities.end() ? &prio->second : nullptr;
    if (r.priority != 0 || config) h += " · priority " + std::to_string(r.priority);
    if (config && config->limit) {
        const auto n = sema::fold(*config->limit, prog);
        h += " · limit " + (n ? std::to_string(std::get<long long>(*n)) : sourceText(sources, config->limit->span)) +
             " (its priority's)";
    }
    if (r.limit) {
        const auto n = sema::fold(*r.limit, prog);
        h += " · limit " + (n ? std::to_string(std::get<long long>(*n)) : sourceText(sources, r.limit->span));
    }
    if (r.pick == ir::Pick::Oldest) h += " · pick oldest";
    if (r.pick == ir::Pick::OldestGeneration) h += " · pick oldest generation";
    if (r.ordered) h += " · ordered";
    if (ir::runsParallel(prog, r)) h += " · parallel";
    return h;
}

}  // namespace

std::string productionsSvg(const ir::Program& prog, const SourceManager& sources, const std::string& title) {
    std::string body;
    double y = 40, width = 2 * kPanel + kGap + 40;
    body += "<text x=\"20\" y=\"24\" font-size=\"16\" font-weight=\"bold\">" + xmlEscape(title) + "</text>\n";
    body += drawPanel(axiomPanel(prog), 20, y + 20);
    y += kPanel + 50;
    for (const auto& r : prog.rules) {
        body += "<text x=\"20\" y=\"" + num(y + 12) + "\" font-size=\"14\" font-weight=\"bold\">" + xmlEscape(ruleHeading(r, prog, sources)) + "</text>\n";
        double lineY = y + 28;
        for (const auto& c : r.conditions) {
            body += "<text x=\"20\" y=\"" + num(lineY) + "\" font-size=\"11\" fill=\"#555555\">where " +
                    xmlEscape(sourceText(sources, c.expr.span)) + "</text>\n";
            lineY += 14;
        }
        if (r.compound >= 0) {   // its initial primitives and values; it has no daughter of its own
            for (const auto& l : r.lets) {
                body += "<text x=\"20\" y=\"" + num(lineY) + "\" font-size=\"11\" fill=\"#555555\">let " + xmlEscape(l.name) + " = " +
                        xmlEscape(sourceText(sources, l.value.span)) + "</text>\n";
                lineY += 14;
            }
            body += drawPanel(motherPanel(prog, r, std::vector<bool>(r.nodes.size(), true)), 20, lineY + 14);
            y = lineY + 14 + kPanel + 50;
            continue;
        }
        std::vector<bool> keptAnywhere(r.nodes.size(), false);
        for (const auto& d : r.daughters)
            for (const auto& n : d.nodes)
                if (n.motherNode >= 0) keptAnywhere[static_cast<std::size_t>(n.motherNode)] = true;
        const Panel mother = motherPanel(prog, r, keptAnywhere);
        const double top = lineY + 14;
        body += drawPanel(mother, 20, top);
        double total = 0;
        bool allKnown = true;
        for (const auto& d : r.daughters) {
            total += d.weight.value_or(0);
            allKnown = allKnown && d.weight.has_value();
        }
        double left = 20 + kPanel + kGap;
        body += "<line x1=\"" + num(20 + kPanel + 10) + "\" y1=\"" + num(top + kPanel / 2) + "\" x2=\"" + num(left - 10) + "\" y2=\"" +
                num(top + kPanel / 2) + "\" stroke=\"#222222\" stroke-width=\"2\" marker-end=\"url(#show-arrow)\"/>\n";
        for (std::size_t i = 0; i < r.daughters.size(); ++i) {
            const auto& d = r.daughters[i];
            std::string caption = "daughter " + std::to_string(i + 1);
            if (r.daughters.size() > 1) {
                caption += d.weight ? " · weight " + rt::formatNumber(*d.weight) : " · weight " + sourceText(sources, d.weightExpr->span);
                if (allKnown && total > 0) caption += " (p = " + num(*d.weight / total) + ")";
            }
            body += drawPanel(daughterPanel(prog, r, d, mother, caption), left, top);
            left += kPanel + 20;
        }
        width = std::max(width, left + 20);
        y = top + kPanel + 50;
    }
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width) +
                      "\" height=\"" + num(y) + "\" viewBox=\"0 0 " + num(width) + " " + num(y) + "\" font-family=\"sans-serif\">\n";
    out += "<defs><marker id=\"show-arrow\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" markerWidth=\"6\" markerHeight=\"6\" "
           "orient=\"auto-start-reverse\"><path d=\"M 0 0 L 10 5 L 0 10 z\" fill=\"#444444\"/></marker></defs>\n";
    out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" + body + "</svg>\n";
    return out;
}

std::string productionsPage(const ir::Program& prog, const SourceManager& sources, const std::string& title) {
    std::string svg = productionsSvg(prog, sources, title);
    svg = svg.substr(svg.find('\n') + 1);   // no XML declaration inside HTML
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + xmlEscape(title) +
           " — productions</title>\n<style>body{font:14px system-ui,sans-serif;margin:16px}</style>\n</head>\n<body>\n"
           "<p>Each production: its mother graph, then each daughter graph. <span style=\"color:#ff8c00\">Orange</span>: "
           "kept (mapped by name; kept nodes keep their place); <span style=\"color:#d62728\">dashed red</span>: deleted; "
           "<span style=\"color:#1a9e3a\">green</span>: new; <span style=\"color:#999999\">dashed grey</span>: a negative "
           "condition (must not be there).</p>\n" +
           svg + "</body>\n</html>\n";
}

}  // namespace g2d::show
