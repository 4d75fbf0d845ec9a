// Real roots of a polynomial of low degree in [0, 1], isolated where its derivative vanishes.
#pragma once

#include "tracer/geometry/geometry_math.hpp"

namespace crt::tracer {

/// The largest degree polynomialRoots takes. Each degree isolates its roots by those of its
/// derivative, so the work grows with its square.
inline constexpr int kMaxPolynomialDegree = 10;

/// Writes to `roots`, ascending, each u in (0, 1) where c[0] + c[1]·u + … + c[degree]·u^degree
/// changes sign, and returns how many. The roots of the derivative (found the same way) split
/// [0, 1] into pieces where the polynomial is monotonic, so each piece holds at most one root;
/// a root of even multiplicity (a touch without a sign change) is not reported.
int polynomialRoots(const double* c, int degree, double* roots);

/// c[0] + c[1]·u + … + c[degree]·u^degree and its derivative, by Horner's rule.
ValueAndSlope evaluatePolynomial(const double* c, int degree, double u);

/// Calls found(u) for each root of g between consecutive splits (ascending, from 0 to 1, g
/// monotonic between them) where g changes sign, refined by bracketedRoot. `value` and `slope`
/// give g and g' at a point; the values at the ends are given, so that pieces meeting at an
/// end agree on its sign.
template <class Value, class Slope, class Found>
void signChangesBetween(const double* split, int n, const Value& value, const Slope& slope,
                        double atStart, double atEnd, const Found& found) {
    double before = atStart;
    for (int i = 0; i + 1 < n; ++i) {
        const double after = i + 2 < n ? value(split[i + 1]) : atEnd;
        if ((before < 0) != (after < 0)) {
            found(bracketedRoot(
                [&](double u) {
                    return ValueAndSlope{value(u), slope(u)};
                },
                split[i], split[i + 1], before < 0));
        }
        before = after;
    }
}

/// Calls found(u) for each u in [0, 1] where g changes sign, g being the polynomial c (as
/// above) but evaluated by `value` and `slope`, which may compute it more accurately than
/// its coefficients do; the values at the ends are given, so that pieces meeting at an end
/// agree on its sign.
template <class Value, class Slope, class Found>
void polynomialSignChanges(const double* c, int degree, const Value& value, const Slope& slope,
                           double atStart, double atEnd, const Found& found) {
    double derivative[kMaxPolynomialDegree];
    for (int k = 1; k <= degree; ++k) derivative[k - 1] = k * c[k];
    double split[kMaxPolynomialDegree + 1];
    split[0] = 0;
    const int turns = degree > 0 ? polynomialRoots(derivative, degree - 1, split + 1) : 0;
    split[turns + 1] = 1;
    signChangesBetween(split, turns + 2, value, slope, atStart, atEnd, found);
}

} // namespace crt::tracer
