# SPDX-License-Identifier: GPL-2.0-or-later
"""SymPy's KanesMethod linearization of the Whipple bicycle, as its test_kane3.py::test_bicycle
builds it (Autolev's frames and names), timed from the first frame to the lean/steer A at
the benchmark's values; prints the seconds and the eigenvalues at v = 5 m/s.
Run by bench/bicycle.sh."""
import sys
import time

start = time.perf_counter()
import mpmath
from sympy import acos, pi, sin, cos, sqrt, symbols
from sympy.physics.mechanics import (KanesMethod, Point, ReferenceFrame, RigidBody, dot, dynamicsymbols,
                                     inertia)

q1, q2, q4, q5 = dynamicsymbols('q1 q2 q4 q5')
u1, u2, u3, u4, u5, u6 = dynamicsymbols('u1 u2 u3 u4 u5 u6')
q1d, q2d, q4d, q5d = dynamicsymbols('q1 q2 q4 q5', 1)
(WFrad, WRrad, htangle, forkoffset, forklength, framelength, forkcg1, forkcg3, framecg1, framecg3, Iwr11, Iwr22,
 Iwf11, Iwf22, Iframe11, Iframe22, Iframe33, Iframe31, Ifork11, Ifork22, Ifork33, Ifork31, g, mframe, mfork, mwf,
 mwr) = symbols('WFrad WRrad htangle forkoffset forklength framelength forkcg1 forkcg3 framecg1 framecg3 Iwr11 '
                'Iwr22 Iwf11 Iwf22 Iframe11 Iframe22 Iframe33 Iframe31 Ifork11 Ifork22 Ifork33 Ifork31 g mframe '
                'mfork mwf mwr')

# yaw, roll, frame pitch (from the head tube angle), fork steer; wheels spin in them
N = ReferenceFrame('N')
Y = N.orientnew('Y', 'Axis', [q1, N.z])
R = Y.orientnew('R', 'Axis', [q2, Y.x])
Frame = R.orientnew('Frame', 'Axis', [q4 + htangle, R.y])
WR = ReferenceFrame('WR')
TempFrame = Frame.orientnew('TempFrame', 'Axis', [-htangle, Frame.y])
Fork = Frame.orientnew('Fork', 'Axis', [q5, Frame.x])
TempFork = Fork.orientnew('TempFork', 'Axis', [-htangle, Fork.y])
WF = ReferenceFrame('WF')

WR_cont = Point('WR_cont')
WR_mc = WR_cont.locatenew('WR_mc', WRrad * R.z)
Steer = WR_mc.locatenew('Steer', framelength * Frame.z)
Frame_mc = WR_mc.locatenew('Frame_mc', -framecg1 * Frame.x + framecg3 * Frame.z)
Fork_mc = Steer.locatenew('Fork_mc', -forkcg1 * Fork.x + forkcg3 * Fork.z)
WF_mc = Steer.locatenew('WF_mc', forklength * Fork.x + forkoffset * Fork.z)
WF_cont = WF_mc.locatenew('WF_cont', WFrad * (dot(Fork.y, Y.z) * Fork.y - Y.z).normalize())

Y.set_ang_vel(N, u1 * Y.z)
R.set_ang_vel(Y, u2 * R.x)
WR.set_ang_vel(Frame, u3 * Frame.y)
Frame.set_ang_vel(R, u4 * Frame.y)
Fork.set_ang_vel(Frame, u5 * Fork.x)
WF.set_ang_vel(Fork, u6 * Fork.y)

WR_cont.set_vel(N, 0)
WR_mc.v2pt_theory(WR_cont, N, WR)
Steer.v2pt_theory(WR_mc, N, Frame)
Frame_mc.v2pt_theory(WR_mc, N, Frame)
Fork_mc.v2pt_theory(Steer, N, Fork)
WF_mc.v2pt_theory(Steer, N, Fork)
WF_cont.v2pt_theory(WF_mc, N, WF)

bodies = [RigidBody('BodyFrame', Frame_mc, Frame, mframe,
                    (inertia(TempFrame, Iframe11, Iframe22, Iframe33, 0, 0, Iframe31), Frame_mc)),
          RigidBody('BodyFork', Fork_mc, Fork, mfork, (inertia(TempFork, Ifork11, Ifork22, Ifork33, 0, 0, Ifork31),
                                                       Fork_mc)),
          RigidBody('BodyWR', WR_mc, WR, mwr, (inertia(Frame, Iwr11, Iwr22, Iwr11), WR_mc)),
          RigidBody('BodyWF', WF_mc, WF, mwf, (inertia(Fork, Iwf11, Iwf22, Iwf11), WF_mc))]
loads = [(Frame_mc, -mframe * g * Y.z), (Fork_mc, -mfork * g * Y.z), (WF_mc, -mwf * g * Y.z),
         (WR_mc, -mwr * g * Y.z)]
KM = KanesMethod(N, q_ind=[q1, q2, q5], q_dependent=[q4],
                 configuration_constraints=[WF_cont.pos_from(WR_cont) & Y.z],
                 u_ind=[u2, u3, u5], u_dependent=[u1, u4, u6],
                 velocity_constraints=[WF_cont.vel(N) & Y.x, WF_cont.vel(N) & Y.y, WF_cont.vel(N) & Y.z],
                 kd_eqs=[q1d - u1, q2d - u2, q4d - u4, q5d - u5], constraint_solver="CRAMER")
KM.kanes_equations(bodies, loads)

# Meijaard's values in these frames (test_kane3.py's conversion)
rF, rR, wb, trail = 0.35, 0.3, 1.02, 0.08
HTA = (pi / 2 - pi / 10).evalf()
rake = (-(trail * sin(HTA) - rF * cos(HTA))).evalf()
ta, tb = 0.7 - rF, wb - 0.9
tc = sqrt(ta ** 2 + tb ** 2).evalf()
fork_l = (wb * cos(HTA) - (rF - rR) * sin(HTA)).evalf()
v = symbols('v')
values = {WFrad: rF, WRrad: rR, htangle: HTA, forkoffset: rake, forklength: fork_l,
          framelength: (wb * sin(HTA) - (rake - (rF - rR) * cos(HTA))).evalf(),
          forkcg1: (tc * cos((pi / 2 - HTA) - acos(ta / tc)) - fork_l).evalf(),
          forkcg3: (rake + (tc * sin(pi / 2 - HTA - acos(ta / tc)))).evalf(),
          framecg1: ((0.9 - rR - (0.3 / sin(HTA)) * cos(HTA)) * sin(HTA)).evalf(),
          framecg3: (0.3 / sin(HTA) + (0.9 - rR - 0.3 / sin(HTA) * cos(HTA)) * cos(HTA)).evalf(),
          Iwr11: 0.0603, Iwr22: 0.12, Iwf11: 0.1405, Iwf22: 0.28, Ifork11: 0.05892, Ifork22: 0.06,
          Ifork33: 0.00708, Ifork31: 0.00756, Iframe11: 9.2, Iframe22: 11, Iframe33: 2.8, Iframe31: -2.4,
          mfork: 4, mframe: 85, mwf: 3, mwr: 2, g: 9.81}
point = {u1: 0, u2: 0, u3: v / rR, u4: 0, u5: 0, u6: v / rF, q1: 0, q2: 0, q4: 0, q5: 0}
point.update({u.diff(): 0 for u in (u1, u2, u3, u4, u5, u6)})
A, B, _ = KM.linearize(A_and_B=True, op_point=point, linear_solver="CRAMER")
A = A.xreplace(values).evalf().extract([1, 2, 3, 5], [1, 2, 3, 5])
seconds = time.perf_counter() - start
eigenvalues, _ = mpmath.eig(mpmath.matrix(A.subs(v, 5).evalf().tolist()))
print(f"{seconds:.3f}")
print(" ".join(repr(complex(x)) for x in sorted(eigenvalues, key=lambda z: (complex(z).imag, complex(z).real))))
