// Real roots of a polynomial in [0, 1] (see polynomial_roots.hpp).
#include "tracer/geometry/polynomial_roots.hpp"

namespace crt::tracer {

ValueAndSlope evaluatePolynomial(const double* c, int degree, double u) {
    double value = c[degree], slope = 0;
    for (int k = degree - 1; k >= 0; --k) {
        slope = slope * u + value;
        value = value * u + c[k];
    }
    return {value, slope};
}

int polynomialRoots(const double* c, int degree, double* roots) {
    while (degree > 0 && c[degree] == 0) --degree;
    if (degree == 0) return 0;
    if (degree == 1) {
        const double u = -c[0] / c[1];
        if (!(u > 0 && u < 1)) return 0;
        roots[0] = u;
        return 1;
    }
    if (degree == 2) { // in closed form: two distinct roots, each a sign change
        double r0, r1;
        int found = 0;
        if (solveQuadratic(c[2], 0.5 * c[1], c[0], r0, r1) && r0 < r1) {
            if (r0 > 0 && r0 < 1) roots[found++] = r0;
            if (r1 > 0 && r1 < 1) roots[found++] = r1;
        }
        return found;
    }
    auto at = [&](double u) { return evaluatePolynomial(c, degree, u); };
    int found = 0;
    polynomialSignChanges(
        c, degree, [&](double u) { return at(u).value; }, [&](double u) { return at(u).slope; },
        c[0], at(1).value,
        [&](double u) {
            if (u > 0 && u < 1) roots[found++] = u;
        });
    return found;
}

} // namespace crt::tracer
