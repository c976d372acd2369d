#!/usr/bin/python3
"""Generates the SH basis evaluators (C++ and GLSL) and the sparse triple-product code.

One source for both languages: the real SH basis in the Sloan/D3DX convention (Condon-Shortley
phase included), index i = l(l+1)+m, order n = n bands = n*n coefficients:
    y_lm = sqrt2 K_l^m cos(m phi) P_l^m(cos theta)   m > 0
    y_lm = sqrt2 K_l^|m| sin(|m| phi) P_l^|m|(cos theta)   m < 0
    y_l0 = K_l^0 P_l(cos theta)
with P_l^m(z) = (-1)^m (1-z^2)^(m/2) d^m/dz^m P_l(z). Writing C_m + i S_m = (x + i y)^m
(= sin^m(theta) e^{i m phi}), every y_lm is a constant times C_m or S_m times a polynomial in z,
which is what the generated code evaluates (Horner in z^2).

The triple-product tensor Gamma_ijk = integral of y_i y_j y_k over the sphere is computed by
exact Gauss-Legendre x uniform-phi quadrature of the same polynomials and written out as
unrolled product/square functions (C++ and GLSL) for orders 3..6 plus a sparse entry table.

Usage: generate_sh.py OUTPUT_DIR   (writes OUTPUT_DIR/sh/{basis_generated.h, sh_basis.glsl,
product_generated.h, product_generated.cpp,
sh_product.glsl}). Never edit the outputs; edit this script.
"""
from fractions import Fraction
import math
import os
import sys

import numpy as np

MAX_BASIS_ORDER = 8
PRODUCT_ORDERS = range(3, 7)
ZERO_THRESHOLD = 1e-10


def legendre_polynomial(l):
    """Coefficients (lowest power first) of P_l as Fractions, by Bonnet's recursion."""
    previous, current = [Fraction(1)], [Fraction(0), Fraction(1)]
    if l == 0:
        return previous
    for k in range(1, l):
        # (k+1) P_{k+1} = (2k+1) z P_k - k P_{k-1}
        nxt = [Fraction(0)] * (k + 2)
        for power, coefficient in enumerate(current):
            nxt[power + 1] += Fraction(2 * k + 1, k + 1) * coefficient
        for power, coefficient in enumerate(previous):
            nxt[power] -= Fraction(k, k + 1) * coefficient
        previous, current = current, nxt
    return current


def derivative(polynomial, times):
    for _ in range(times):
        polynomial = [power * c for power, c in enumerate(polynomial)][1:] or [Fraction(0)]
    return polynomial


def basis_terms(order):
    """For each index: (l, m, scale, z-polynomial coefficients) with y = scale * T_m * poly(z),
    T_m = C_|m| (m >= 0) or S_|m| (m < 0)."""
    terms = []
    for l in range(order):
        for m in range(-l, l + 1):
            am = abs(m)
            k = math.sqrt((2 * l + 1) / (4 * math.pi) * math.factorial(l - am) / math.factorial(l + am))
            scale = k if m == 0 else math.sqrt(2.0) * k * (-1) ** am
            poly = derivative(legendre_polynomial(l), am)
            terms.append((l, m, scale, [float(c) for c in poly]))
    return terms


def format_float(value):
    return repr(float(value))


def polynomial_expression(coefficients, real):
    """Horner form in z2 (and an outer z for odd parity); coefficients lowest power first."""
    nonzero = [p for p, c in enumerate(coefficients) if c != 0.0]
    odd = nonzero[0] % 2 == 1
    even_part = [coefficients[p] for p in range(1 if odd else 0, len(coefficients), 2)]
    expression = None
    for c in reversed(even_part):
        literal = f"{real}({format_float(c)})"
        expression = literal if expression is None else f"({literal} + z2 * {expression})"
    return (f"z * {expression}" if odd else expression), odd


def basis_body(order, real, out):
    lines = []
    if order > 2:
        lines.append(f"  const {real} z2 = z * z;")
    if order > 1:
        lines.append(f"  const {real} c1 = x;")
        lines.append(f"  const {real} s1 = y;")
    for m in range(2, order):
        lines.append(f"  const {real} c{m} = x * c{m-1} - y * s{m-1};")
        lines.append(f"  const {real} s{m} = x * s{m-1} + y * c{m-1};")
    for index, (l, m, scale, poly) in enumerate(basis_terms(order)):
        coefficients = [scale * c for c in poly]
        poly_text, _ = polynomial_expression(coefficients, real)
        azimuth = "" if m == 0 else (f"c{m} * " if m > 0 else f"s{-m} * ")
        lines.append(f"  {out}[{index}] = {azimuth}{poly_text};  // l={l} m={m}")
    return "\n".join(lines)


def evaluate_basis_numpy(order, x, y, z):
    """Same polynomials as the generated code, in float64, for the tensor quadrature."""
    c = [np.ones_like(x), x]
    s = [np.zeros_like(x), y]
    for m in range(2, order):
        c.append(x * c[m - 1] - y * s[m - 1])
        s.append(x * s[m - 1] + y * c[m - 1])
    values = []
    for l, m, scale, poly in basis_terms(order):
        p = np.polynomial.polynomial.polyval(z, poly)
        azimuth = c[m] if m >= 0 else s[-m]
        values.append(scale * azimuth * p)
    return np.array(values)


def triple_product_tensor(order):
    count = order * order
    nodes, weights = np.polynomial.legendre.leggauss(2 * order + 2)  # exact for degree 3(n-1)
    phi_count = 4 * order + 4
    phi = (np.arange(phi_count) + 0.5) * 2 * math.pi / phi_count
    z = np.repeat(nodes, phi_count)
    w = np.repeat(weights, phi_count) * (2 * math.pi / phi_count)
    sin_theta = np.sqrt(1 - z * z)
    x = sin_theta * np.tile(np.cos(phi), len(nodes))
    y = sin_theta * np.tile(np.sin(phi), len(nodes))
    basis = evaluate_basis_numpy(order, x, y, z)
    gamma = np.einsum("iq,jq,kq,q->ijk", basis, basis, basis, w)
    gamma[np.abs(gamma) < ZERO_THRESHOLD] = 0.0
    assert gamma.shape == (count, count, count)
    return gamma


def balanced_sum(terms):
    """Sum as a balanced tree: short dependency chains let the CPU overlap the additions."""
    if len(terms) == 1:
        return terms[0]
    middle = len(terms) // 2
    return f"({balanced_sum(terms[:middle])} + {balanced_sum(terms[middle:])})"


def load_inputs(names, count, glsl):
    """Copies the inputs to locals so C++ stores to out cannot alias later reads."""
    if glsl:
        return []
    return [f"  const float {name}{i} = {name}[{i}];" for name in names for i in range(count)]


def product_body(gamma, a, b, out, glsl):
    count = gamma.shape[0]
    suffix = "" if glsl else "f"
    ref_a = (lambda j: f"{a}[{j}]") if glsl else (lambda j: f"{a}{j}")
    ref_b = (lambda k: f"{b}[{k}]") if glsl else (lambda k: f"{b}{k}")
    lines = load_inputs([a, b], count, glsl)
    for i in range(count):
        terms = []
        for j in range(count):
            for k in range(count):
                if gamma[i, j, k] != 0.0:
                    terms.append(f"{format_float(gamma[i, j, k])}{suffix} * {ref_a(j)} * {ref_b(k)}")
        lines.append(f"  {out}[{i}] = " + (balanced_sum(terms) if terms else "0.0" + suffix) + ";")
    return "\n".join(lines)


def square_body(gamma, a, out, glsl):
    count = gamma.shape[0]
    suffix = "" if glsl else "f"
    ref = (lambda j: f"{a}[{j}]") if glsl else (lambda j: f"{a}{j}")
    lines = load_inputs([a], count, glsl)
    for i in range(count):
        terms = []
        for j in range(count):
            for k in range(j, count):
                if gamma[i, j, k] != 0.0:
                    value = gamma[i, j, k] * (1.0 if j == k else 2.0)
                    terms.append(f"{format_float(value)}{suffix} * {ref(j)} * {ref(k)}")
        lines.append(f"  {out}[{i}] = " + (balanced_sum(terms) if terms else "0.0" + suffix) + ";")
    return "\n".join(lines)


HEADER_NOTE = "// GENERATED by src/sh/codegen/generate_sh.py; do not edit. Convention: real SH, Condon-Shortley\n" \
              "// phase, index l(l+1)+m, order n = n*n coefficients (see src/sh/basis.h).\n"


def write_text(path, text):
    """Writes through a temporary so an interrupted build never leaves a half-written file."""
    temporary = path + ".tmp"
    with open(temporary, "w", encoding="utf-8") as file:
        file.write(text)
    os.replace(temporary, path)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: generate_sh.py OUTPUT_DIR")
    directory = os.path.join(sys.argv[1], "sh")
    os.makedirs(directory, exist_ok=True)

    cpp = [HEADER_NOTE, "#pragma once\n\nnamespace proxygi::sh::generated {\n",
           f"inline constexpr int kMaxBasisOrder = {MAX_BASIS_ORDER};\n"]
    glsl = [HEADER_NOTE, "#ifndef PROXYGI_SH_BASIS_GLSL\n#define PROXYGI_SH_BASIS_GLSL\n"]
    for order in range(1, MAX_BASIS_ORDER + 1):
        count = order * order
        unused = "  (void)x; (void)y; (void)z;\n" if order == 1 else ""
        cpp.append(f"\n// Writes the {count} basis values at the unit direction (x, y, z) to out[0..{count - 1}].\n"
                   f"template <class Real>\ninline void eval_basis_{order}(Real x, Real y, Real z, Real* out) {{\n"
                   f"{unused}{basis_body(order, 'Real', 'out')}\n}}\n")
        glsl.append(f"\n// The {count} basis values at the unit direction dir.\n"
                    f"void sh_eval_basis_{order}(vec3 dir, out float basis[{count}]) {{\n"
                    f"  const float x = dir.x;\n  const float y = dir.y;\n  const float z = dir.z;\n"
                    + basis_body(order, "float", "basis") + "\n}\n")
    cpp.append("\n}  // namespace proxygi::sh::generated\n")

    glsl_product = [HEADER_NOTE, "#ifndef PROXYGI_SH_PRODUCT_GLSL\n#define PROXYGI_SH_PRODUCT_GLSL\n"]
    product_header = [HEADER_NOTE, "#pragma once\n#include <cstdint>\n\nnamespace proxygi::sh::generated {\n\n"
                      "// One non-zero Gamma_ijk = integral of y_i y_j y_k, listed once per unordered triple\n"
                      "// (i <= j <= k); every permutation has the same value.\n"
                      "struct TripleProductEntry {\n  std::uint16_t i, j, k;\n  double value;\n};\n\n"
                      f"inline constexpr int kMinProductOrder = {PRODUCT_ORDERS.start};\n"
                      f"inline constexpr int kMaxProductOrder = {PRODUCT_ORDERS.stop - 1};\n"]
    product_source = [HEADER_NOTE, '#include "sh/product_generated.h"\n\nnamespace proxygi::sh::generated {\n']
    for order in PRODUCT_ORDERS:
        count = order * order
        gamma = triple_product_tensor(order)
        unique = [(i, j, k, gamma[i, j, k]) for i in range(count) for j in range(i, count)
                  for k in range(j, count) if gamma[i, j, k] != 0.0]
        product_header.append(
            f"\n// Order {order}: {int(np.count_nonzero(gamma))} ordered non-zero entries, {len(unique)} unique.\n"
            f"inline constexpr int kTripleProductEntryCount{order} = {len(unique)};\n"
            f"extern const TripleProductEntry kTripleProductEntries{order}[{len(unique)}];\n"
            f"// out = a * b (projected product, truncated to order {order}); out must not alias a or b.\n"
            f"void product_{order}(const float* a, const float* b, float* out);\n"
            f"// out = a * a; out must not alias a.\nvoid square_{order}(const float* a, float* out);\n")
        entries = ",\n".join(f"    {{{i}, {j}, {k}, {format_float(v)}}}" for i, j, k, v in unique)
        product_source.append(
            f"\nconst TripleProductEntry kTripleProductEntries{order}[{len(unique)}] = {{\n{entries}}};\n"
            f"\nvoid product_{order}(const float* a, const float* b, float* out) {{\n"
            f"{product_body(gamma, 'a', 'b', 'out', False)}\n}}\n"
            f"\nvoid square_{order}(const float* a, float* out) {{\n{square_body(gamma, 'a', 'out', False)}\n}}\n")
        glsl_product.append(f"\n// c = a * b, the order-{order} projected SH product.\n"
                    f"void sh_product_{order}(float a[{count}], float b[{count}], out float c[{count}]) {{\n"
                    f"{product_body(gamma, 'a', 'b', 'c', True)}\n}}\n"
                    f"\n// c = a * a.\nvoid sh_square_{order}(float a[{count}], out float c[{count}]) {{\n"
                    f"{square_body(gamma, 'a', 'c', True)}\n}}\n")
    product_header.append("\n}  // namespace proxygi::sh::generated\n")
    product_source.append("\n}  // namespace proxygi::sh::generated\n")
    glsl.append("\n#endif  // PROXYGI_SH_BASIS_GLSL\n")
    glsl_product.append("\n#endif  // PROXYGI_SH_PRODUCT_GLSL\n")

    write_text(os.path.join(directory, "basis_generated.h"), "".join(cpp))
    write_text(os.path.join(directory, "sh_basis.glsl"), "".join(glsl))
    write_text(os.path.join(directory, "sh_product.glsl"), "".join(glsl_product))
    write_text(os.path.join(directory, "product_generated.h"), "".join(product_header))
    write_text(os.path.join(directory, "product_generated.cpp"), "".join(product_source))


if __name__ == "__main__":
    main()
