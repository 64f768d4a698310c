#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Derives the damped inextensible-catenary ODEs of the frobenius solver (sympy): Gale (1976)
eqs. 2.33a,b, 2.34 in a viscous medium with distinct drag (eta1 tangential, eta2 normal), motion
~ e^(lambda t), lambda in units of sqrt(g/a). Inertia plus drag per unit length, in units of m g/a:
  tangential  mu1 = lambda^2 + eta1 lambda          (mass m)
  normal      mu2 = mu lambda^2 + eta2 lambda       (mass M = mu m, in plane and out of plane)
(Gale's form has mu = 1; the undamped equations are mu1 = -W2, mu2 = -mu W2.)
Unknowns as in frobenius_derive_odes.py: u tangential, w normal, phi rotation, tau tension / H.
  inextensibility          u' = w / C^2                                   (2.33c)
  rotation                 phi = w' + u / C^2
  tangential equilibrium   tau' = phi / C + mu1 u                         (2.33a)
  normal equilibrium       (C phi)' = -tau / C^2 + mu2 w                  (2.33b)
  out of plane             (C v')' - mu2 v = 0                            (2.34)
Checks: (1) the sigma form against the equation of the brief (Gale's 2.35 with omega^2 -> -mu);
(2) the eta = |xi| form: coefficients polynomial in eta, mu1 only in p0, mu2 where mu W2 stood;
(3) the tension (2.37) with mu2.
"""
import sympy as sp

s = sp.symbols('sigma', real=True)
m1, m2 = sp.symbols('mu1 mu2')
C = sp.sqrt(1 + s**2)
U = sp.Function('U')(s)

w = C**2 * U.diff(s)
phi = w.diff(s) + U / C**2
tau = -C**2 * ((C * phi).diff(s) - m2 * w)
residual = tau.diff(s) - phi / C - m1 * U
D = sp.symbols('D0:5')


def to_syms(e):
    for k in range(4, 0, -1):
        e = e.subs(U.diff(s, k), D[k])
    return sp.expand(e.subs(U, D[0]))


residual = to_syms(residual)
lead = sp.simplify(residual.coeff(D[4]))
res_n = sp.expand(sum(sp.simplify(residual.coeff(D[k]) / lead * C**5) * D[k] for k in range(5)))
brief = (C**5 * U.diff(s, 4) + 10 * s * C**3 * U.diff(s, 3)
         + (3 * (3 + 8 * s**2) * C - m2 * C**4) * U.diff(s, 2)
         + 4 * s * C * (3 - m2 * C) * U.diff(s))
print('lead of U\'\'\'\':', lead, ' (residual / lead * C^5 is the sigma form)')
# Gale's printed 2.35 has + Omega^2 U, a sign slip (frobenius_derive_odes.py): the brief's - mu1 U
# inherits it; the derivation gives + mu1 U (= - Omega^2 U undamped).
print('sigma form - (2.35, omega^2 -> -mu, printed sign of U):',
      sp.simplify(res_n - to_syms(brief - m1 * U)))
print('sigma form - (2.35, omega^2 -> -mu, + mu1 U):', sp.simplify(res_n - to_syms(brief + m1 * U)))
gale237 = (s / C * U - ((3 + 4 * s**2) * C - m2 * C**4) * U.diff(s)
           - (C**5 * U.diff(s, 2)).diff(s))
print('tau - (2.37 with mu W2 -> -mu2):', sp.simplify(to_syms(tau) - to_syms(gale237)))

eta = sp.symbols('eta', positive=True)
sig, Cs = sp.symbols('sig Cs', positive=True)
q = eta * (2 + eta)
Y = sp.symbols('Y0:5')


def dsig(e):
    e = e.subs(Cs, 1 + eta)
    out = 0
    for k in range(4):
        c = e.coeff(Y[k])
        out += (sig / (1 + eta)) * (sp.diff(c, eta) * Y[k] + c * Y[k + 1])
        out += sp.diff(c, sig) * Y[k]
    return sp.expand(out)


def reduce_sig(e):
    poly = sp.Poly(sp.expand(e), sig)
    return sp.expand(sum(c * q**(p // 2) * sig**(p % 2) for (p,), c in poly.terms()))


ders = [Y[0]]
for k in range(4):
    ders.append(reduce_sig(dsig(ders[-1])))
expr = 0
for k in range(5):
    ck = res_n.coeff(D[k]).subs(sp.sqrt(s**2 + 1), Cs).subs(s, sig).subs(Cs, 1 + eta)
    expr += ck * ders[k]
expr = reduce_sig(sp.together(sp.expand(expr)))
coeffs = [sp.factor(sp.simplify(expr.coeff(Y[k]))) for k in range(5)]
scale = sp.simplify(coeffs[4] / (eta**2 * (1 + eta) * (2 + eta)**2))
print('scale to Gale form:', scale)
# What the solver encodes (frobenius_catenary.hpp, catenary_ode with w2 -> -mu1, mu w2 -> -mu2):
solver = [m1, 6 * (1 + 4 * eta + 2 * eta**2) - m2 * (1 + eta) * (1 + 8 * eta + 4 * eta**2),
          3 * (1 + eta) * (1 + 16 * eta + 8 * eta**2) - m2 * eta * (1 + eta)**2 * (2 + eta),
          2 * eta * (2 + eta) * (3 + 10 * eta + 5 * eta**2), eta**2 * (1 + eta) * (2 + eta)**2]
for k in range(5):
    pk = sp.expand(sp.simplify(coeffs[k] / scale))
    print(f'in-plane p{k}(eta) =', sp.collect(pk, [m1, m2]), '  | minus solver:',
          sp.simplify(pk - sp.expand(solver[k])))

e2 = Cs * ders[2] + (sig / Cs) * ders[1] - m2 * ders[0]
e2 = reduce_sig(sp.expand(e2.subs(Cs, 1 + eta) * (1 + eta)))
solver2 = [-m2 * (1 + eta), 1 + eta, eta * (2 + eta)]
for k in range(3):
    print(f'out-of-plane p{k}(eta) =', sp.factor(e2.coeff(Y[k])), '  | minus solver:',
          sp.simplify(e2.coeff(Y[k]) - solver2[k]))
