// Graphviz dump of the graph: passes as boxes (culled ones dashed), resource versions as ellipses
// (imports filled), edges version -> pass for reads and pass -> version for writes.
#include "graph/graph.hpp"

#include <set>
#include <sstream>

namespace ppr::graph {

namespace {

// Quotes s for DOT; `suffix` is appended verbatim (so it may hold DOT escapes such as \n).
std::string quoted(const std::string& s, const char* suffix = "") {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + suffix + '"';
}

std::string versionNode(uint32_t resource, uint32_t version) {
    return "r" + std::to_string(resource) + "v" + std::to_string(version);
}

}  // namespace

std::string RenderGraph::toDot() const {
    std::ostringstream dot;
    dot << "digraph rendergraph {\n  rankdir=LR;\n  node [fontname=\"Helvetica\"];\n";
    std::set<std::pair<uint32_t, uint32_t>> versions;
    std::ostringstream edges;
    for (uint32_t i = 0; i < passes_.size(); ++i) {
        const Pass& pass = passes_[i];
        const bool culled = i < compiled_.size() && compiled_[i].culled;
        const std::string node = "p" + std::to_string(i);
        dot << "  " << node << " [shape=box, "
            << (culled ? "style=dashed, label=" + quoted(pass.name, "\\n(culled)") : "label=" + quoted(pass.name))
            << "];\n";
        for (const ResourceUse& u : pass.uses) {
            const std::string label = quoted(accessName(u.access));
            if (readsContents(pass, u)) {
                versions.insert({u.resource, u.versionRead});
                edges << "  " << versionNode(u.resource, u.versionRead) << " -> " << node << " [label=" << label
                      << "];\n";
            }
            if (u.versionWritten > 0) {
                versions.insert({u.resource, u.versionWritten});
                edges << "  " << node << " -> " << versionNode(u.resource, u.versionWritten) << " [label=" << label
                      << "];\n";
            }
        }
    }
    for (const auto& [resource, version] : versions) {
        dot << "  " << versionNode(resource, version) << " [shape=ellipse, label="
            << quoted(resources_[resource].name + " v" + std::to_string(version))
            << (isImported(resource) ? ", style=filled, fillcolor=lightblue" : "") << "];\n";
    }
    dot << edges.str() << "}\n";
    return dot.str();
}

}  // namespace ppr::graph
