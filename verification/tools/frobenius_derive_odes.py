#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Derives the inextensible-catenary ODEs used by the frobenius solver (sympy), checks them against
Gale (1976) eqs. 2.35, 2.37, 2.42, 2.44, and prints the polynomial coefficients of the equations in
eta = |xi| that src/solvers/frobenius/frobenius_odes.cpp encodes.

Model (docs/explanation/physics.md, "Linear dynamics", EA = inf), lengths in units of a = H/W0, tension in units of H, sigma = s/a
measured from the apex, C = sqrt(1+sigma^2) (static tension / H), curvature 1/(a C^2).
Unknowns: u (tangential), w (normal), phi = rotation of the tangent, tau = dynamic tension.
  inextensibility          u' = w / C^2
  rotation                 phi = w' + u / C^2
  tangential equilibrium   tau' = phi / C - W2 u             (W2 = Omega^2 = w^2 a m / W0)
  normal equilibrium       (C phi)' = -tau / C^2 - mu W2 w   (mu = M / m)
Out of plane: (C v')' + mu W2 v = 0.
"""
import sympy as sp

s = sp.symbols('sigma', real=True)
W2, mu = sp.symbols('W2 mu', positive=True)
C = sp.sqrt(1 + s**2)
U = sp.Function('U')(s)

w = C**2 * U.diff(s)
phi = w.diff(s) + U / C**2
tau = -C**2 * ((C * phi).diff(s) + mu * W2 * w)
residual = tau.diff(s) - phi / C + W2 * U
Dsym = sp.symbols('D0:5')
def to_syms(e):
    for k in range(4, 0, -1):
        e = e.subs(U.diff(s, k), Dsym[k])
    return sp.expand(e.subs(U, Dsym[0]))
residual = to_syms(residual)
# Gale 2.35 (mu = 1), multiplied so that the U'''' coefficient is C^5:
lead = sp.simplify(residual.coeff(Dsym[4]))
res_n = sp.expand(sum(sp.simplify(residual.coeff(Dsym[k]) / lead * C**5) * Dsym[k] for k in range(5)))
gale235 = (C**5 * U.diff(s, 4) + 10 * s * C**3 * U.diff(s, 3)
           + (3 * (3 + 8 * s**2) * C + W2 * C**4) * U.diff(s, 2)
           + 4 * s * C * (3 + W2 * C) * U.diff(s) + W2 * U)
print('lead coefficient of U\'\'\'\' in our residual:', lead)
print('ours - Gale 2.35 (mu=1):', sp.simplify(res_n.subs(mu, 1) - to_syms(gale235)))
# Gale's 2.37 tension (sign: Gale's T)
gale237 = s / C * U - ((3 + 4 * s**2) * C + W2 * C**4) * U.diff(s) - (C**5 * U.diff(s, 2)).diff(s)
print('our tau / Gale T (mu=1):', sp.simplify((tau.subs(mu, 1)) / gale237))
print('our tau - Gale T (mu=1):', sp.simplify(tau.subs(mu, 1) - gale237))

# Change of variable eta = C - 1 (= |xi|), sigma^2 = q = eta (2 + eta) on either side: d/dsigma =
# (sigma/C) d/deta. Work with symbols sig, Cs and reduce sig^2 -> q at the end.
eta = sp.symbols('eta', positive=True)
sig, Cs = sp.symbols('sig Cs', positive=True)
q = eta * (2 + eta)
Ysym = sp.symbols('Y0:5')
def dsig(e):
    # e is a polynomial in Ysym with coefficients in eta, sig, Cs (Cs = 1 + eta)
    e = e.subs(Cs, 1 + eta)
    out = 0
    for k in range(4):
        c = e.coeff(Ysym[k])
        out += (sig / (1 + eta)) * (sp.diff(c, eta) * Ysym[k] + c * Ysym[k + 1])
    # d/dsigma of sig itself: d sig / d sigma = 1 (sig is sigma)
    for k in range(4):
        c = e.coeff(Ysym[k])
        out += sp.diff(c, sig) * Ysym[k]
    return sp.expand(out)
def reduce_sig(e):
    e = sp.expand(e)
    poly = sp.Poly(e, sig)
    out = 0
    for (p,), c in poly.terms():
        out += c * q**(p // 2) * sig**(p % 2)
    return sp.expand(out)
ders = [Ysym[0]]
for k in range(4):
    ders.append(reduce_sig(dsig(ders[-1])))
expr = 0
for k in range(5):
    ck = res_n.coeff(Dsym[k]).subs(sp.sqrt(s**2 + 1), Cs).subs(s, sig).subs(Cs, 1 + eta)
    expr += ck * ders[k]
expr = reduce_sig(sp.together(sp.expand(expr)) * 1)
coeffs = [sp.factor(sp.simplify(expr.coeff(Ysym[k]))) for k in range(5)]
scale = sp.simplify(coeffs[4] / (eta**2 * (1 + eta) * (2 + eta)**2))
print('scale to Gale form:', scale)
gale242 = [-W2, 6 * (1 + 4 * eta + 2 * eta**2) + W2 * (1 + eta) * (1 + 8 * eta + 4 * eta**2),
           3 * (1 + eta) * (1 + 16 * eta + 8 * eta**2) + W2 * eta * (1 + eta)**2 * (2 + eta),
           2 * eta * (2 + eta) * (3 + 10 * eta + 5 * eta**2), eta**2 * (1 + eta) * (2 + eta)**2]
for k in range(5):
    pk = sp.expand(sp.simplify(coeffs[k] / scale))
    print(f'in-plane p{k}(eta) =', sp.collect(pk, [W2, mu]), '   | ours - Gale 2.42 (mu=1):',
          sp.simplify(pk.subs(mu, 1) - sp.expand(gale242[k])))
    for part, name in ((pk.subs({W2: 0}), 'const'), (pk.coeff(W2).subs(mu, 0), 'W2'),
                       (pk.coeff(W2).coeff(mu), 'W2*mu')):
        print('   ', name, sp.Poly(part, eta).all_coeffs()[::-1] if part != 0 else [0])

# Out of plane: (C v')' + mu W2 v = 0  ->  C v'' + (sigma/C) v' + mu W2 v = 0 in sigma
e2 = Cs * ders[2] + (sig / Cs) * ders[1] + mu * W2 * ders[0]
e2 = reduce_sig(sp.expand(e2.subs(Cs, 1 + eta) * (1 + eta)))
for k in range(3):
    print(f'out-of-plane p{k}(eta) =', sp.factor(e2.coeff(Ysym[k])))
