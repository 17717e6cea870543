#pragma once
// The three tunnel detection methods compared in the paper's Table 1: PG&C (ours), R&L
// (RANSAC + least-squares planes, then the same template fit) and Qhull (convex hull + axial
// alignment). Selected everywhere with --method pgc|ransac|qhull.
#include <string>
#include <vector>

namespace tunnelmap {

enum class Method { Pgc, Ransac, Qhull };

const char* method_name(Method m);          // "pgc", "ransac", "qhull"
const char* method_display_name(Method m);  // "PG&C", "RANSAC & LSE", "Qhull"
// Throws ParameterError (one line) for anything but pgc|ransac|qhull.
Method parse_method(const std::string& name);
// Comma-separated list, e.g. "pgc,qhull".
std::vector<Method> parse_methods(const std::string& list);

}  // namespace tunnelmap
