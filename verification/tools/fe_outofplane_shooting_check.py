#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Naive, independent check of the out-of-plane frequency ratios of Gale's inextensible catenary
# (used as evidence for the Table B-4 entries that disagree with the fe solver; see
# verification/comparisons/fe-gale-B3-B4-comparison.csv). Pure Python, no dependencies:
# shooting on (T v')' + w^2 v = 0 with T = sqrt(1 + s^2) (a = H/W0 = 1 m, W0 = 1 N/m, m = 1 kg/m,
# so w is Gale's ratio), s = sigma in [sigma(xi1), sigma(xi2)], v(sigma1) = 0, classical RK4 with
# 3000 steps (error ~1e-6 here), roots of v(sigma2; w) by scan (step 0.02) and bisection.
# Run: python3 verification/tools/fe_outofplane_shooting_check.py   (about 15 s)
# Output (2026-11-23):
#   -2.223 2.223 ['0.76401', '1.36585', '2.04005', '2.70671', '3.37767', '4.04907']
#   0.153 3.367 ['1.31978', '2.63815', '3.95508', '5.27220', '6.58947', '7.90684']
#   -0.027 2.034 ['1.31031', '2.58037', '3.85456', '5.13206', '6.41089', '7.69036']
import math, sys
def shoot(w, s1, s2, n=3000):
    h=(s2-s1)/n; v,p=0.0,1.0; s=s1
    for i in range(n):
        def f(s,v,p): return p/math.sqrt(1+s*s), -w*w*v
        a1,b1=f(s,v,p); a2,b2=f(s+h/2,v+h/2*a1,p+h/2*b1); a3,b3=f(s+h/2,v+h/2*a2,p+h/2*b2); a4,b4=f(s+h,v+h*a3,p+h*b3)
        v+=h/6*(a1+2*a2+2*a3+a4); p+=h/6*(b1+2*b2+2*b3+b4); s+=h
    return v
sg=lambda xi: math.copysign(math.sqrt((1+abs(xi))**2-1), xi)
def roots(xi1, xi2, nroots=6, dw=0.02):
    s1,s2=sg(xi1),sg(xi2); out=[]; w=dw; f0=shoot(w,s1,s2)
    while len(out)<nroots:
        f1=shoot(w+dw,s1,s2)
        if f0*f1<0:
            lo,hi,flo=w,w+dw,f0
            for _ in range(30):
                mid=(lo+hi)/2; fm=shoot(mid,s1,s2)
                if flo*fm<=0: hi=mid
                else: lo,flo=mid,fm
            out.append((lo+hi)/2)
        w+=dw; f0=f1
    return out
for xi1,xi2 in [(-2.223,2.223),(0.153,3.367),(-0.027,2.034)]:
    print(xi1,xi2,["%.5f"%r for r in roots(xi1,xi2)])
