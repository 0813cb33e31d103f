"""Terminal velocity of the settling sphere against a drag correlation.

Reads postProcessing/fbmBodies/0/sphere.dat (columns Time Fx Fy Fz Tx Ty Tz
x y z Ux Uy Uz wx wy wz), takes the settling speed at the end of the run
and compares it with:
- Schiller & Naumann (1933): C_D = 24/Re (1 + 0.15 Re^0.687), Re < 800,
  solved with the force balance (rho_s - rho_f) g V = C_D rho_f U^2 A / 2
  for an unbounded fluid;
- the same times the wall factor of Di Felice (1996, Int. J. Multiphase
  Flow 22, 527) for a sphere in a tube of diameter D:
  f = ((1 - l)/(1 - 0.33 l))^a, a = (3.3 + 0.085 Re)/(1 + 0.1 Re), l = d/D,
  with D the width of the square box (an approximation: the box is square,
  and closed below and above).
Usage: /usr/bin/python3 terminalVelocity.py [CASE]
"""
import math
import os
import sys

case = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
rho_s, rho_f, nu, g, d, D = 1.5, 1.0, 0.1, 980.0, 0.1, 0.5

rows = [[float(x) for x in l.split()]
        for l in open(os.path.join(case, 'postProcessing/fbmBodies/0/sphere.dat'))
        if not l.startswith('#')]
t, v = rows[-1][0], -rows[-1][11]
v_prev = -[r for r in rows if r[0] <= 0.8*t][-1][11]


def schillerNaumann():
    U = (rho_s - rho_f)*g*d**2/(18*rho_f*nu)          # Stokes, first guess
    for _ in range(200):
        Re = U*d/nu
        Cd = 24/Re*(1 + 0.15*Re**0.687)
        U = math.sqrt(4*(rho_s - rho_f)*g*d/(3*rho_f*Cd))
    return U


U_inf = schillerNaumann()
Re = U_inf*d/nu
lam = d/D
alpha = (3.3 + 0.085*Re)/(1 + 0.1*Re)
f = ((1 - lam)/(1 - 0.33*lam))**alpha
U_wall = U_inf*f
print('fbmFoam: settling speed %.4f at t = %g (%.4f at t = %g)' % (v, t, v_prev, 0.8*t))
print('Schiller-Naumann, unbounded: %.4f (Re = %.3f)' % (U_inf, Re))
print('with the Di Felice wall factor %.3f (d/D = %.2f): %.4f' % (f, lam, U_wall))
print('fbmFoam / correlation with wall factor: %.3f' % (v/U_wall))
