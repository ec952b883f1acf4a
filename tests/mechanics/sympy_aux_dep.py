# SymPy's test_aux_dep (sympy/physics/mechanics/tests/test_kane2.py): the rolling disc with
# its height a dependent coordinate and the contact point's auxiliary speeds ua0..ua2, solved
# for the contact forces Fx, Fy, Fz (along the heading frame A). Prints, at seeded random
# states, the state in test_contact.cpp's coordinates (yaw, lean, spin, x, y, z and their
# rates, u' from the equations of motion) and the force in the scene's axes N.
import random
import mpmath
from sympy import Matrix, symbols, solve, lambdify, cos, sin
from sympy.physics.mechanics import (dynamicsymbols, ReferenceFrame, Point, RigidBody, KanesMethod, inertia, dot, cross)
t = dynamicsymbols._t
r, m, g, I, J = symbols('r m g I J')
Fx, Fy, Fz = symbols('Fx Fy Fz')
q = dynamicsymbols('q:4'); qd = [x.diff(t) for x in q]
u = dynamicsymbols('u:6'); ua = dynamicsymbols('ua:3')
N = ReferenceFrame('N')
A = N.orientnew('A', 'Axis', [q[0], N.z])
B = A.orientnew('B', 'Axis', [q[1], A.x])
C = B.orientnew('C', 'Axis', [q[2], B.y])
C.set_ang_vel(N, u[0]*B.x + u[1]*B.y + u[2]*B.z)
C.set_ang_acc(N, C.ang_vel_in(N).diff(t, B) + cross(B.ang_vel_in(N), C.ang_vel_in(N)))
P = Point('P')
P.set_vel(N, ua[0]*A.x + ua[1]*A.y + ua[2]*A.z)
O = P.locatenew('O', q[3]*A.z + r*sin(q[1])*A.y)
O.set_vel(N, u[3]*A.x + u[4]*A.y + u[5]*A.z)
O.set_acc(N, O.vel(N).diff(t, A) + cross(A.ang_vel_in(N), O.vel(N)))
w_c_n_qd = qd[0]*A.z + qd[1]*B.x + qd[2]*B.y
v_o_n_qd = O.pos_from(P).diff(t, A) + cross(A.ang_vel_in(N), O.pos_from(P))
kindiffs = Matrix([dot(w_c_n_qd - C.ang_vel_in(N), uv) for uv in B] + [dot(v_o_n_qd - O.vel(N), A.z)])
f_c = Matrix([dot(-r*B.z, A.z) - q[3]])
f_v = Matrix([dot(O.vel(N) - (P.vel(N) + cross(C.ang_vel_in(N), O.pos_from(P))), ai).expand() for ai in A])
disc = RigidBody('disc', O, C, m, (inertia(B, I, J, I), O))
kane = KanesMethod(N, q_ind=q[:3], u_ind=u[:3], kd_eqs=kindiffs, q_dependent=q[3:],
                   configuration_constraints=f_c, u_dependent=u[3:], velocity_constraints=f_v, u_auxiliary=ua)
kane.kanes_equations([disc], [(O, m*g*A.z), (P, Fx*A.x + Fy*A.y + Fz*A.z)])
kdd = kane.kindiffdict()
forces = solve(list(kane.auxiliary_eqs.subs(kdd).subs({x.diff(t): 0 for x in ua}).subs({x: 0 for x in ua})), [Fx, Fy, Fz], dict=True)[0]
ud = [x.diff(t) for x in u]
# u' of every speed from the equations of motion (the constraint rows included)
params = {m: 1.3, g: 9.81, r: 0.4, I: 0.07, J: 0.11}
state = q + u
no_aux = {x: 0 for x in ua}
no_aux.update({x.diff(t): 0 for x in ua})
mass = lambdify(state, kane.mass_matrix.subs(kdd).subs(no_aux).subs(params).tolist(), 'math')
forcing = lambdify(state, kane.forcing.subs(kdd).subs(no_aux).subs(params).tolist(), 'math')
F_N = [forces[F].subs(params) for F in (Fx, Fy, Fz)]
F_A = Matrix(F_N)
# scene axes: the force F_x A.x + F_y A.y + F_z A.z in N
force_N = lambdify(state + ud, [F_A[0]*cos(q[0]) - F_A[1]*sin(q[0]), F_A[0]*sin(q[0]) + F_A[1]*cos(q[0]), F_A[2]], 'math')
vel_O = O.vel(N).express(N)
v_O = lambdify(state, [vel_O.dot(N.x), vel_O.dot(N.y), vel_O.dot(N.z)], 'math')
u_dep = solve(list(f_v.subs({x: 0 for x in ua})), u[3:], dict=True)[0]
u_dep_f = lambdify(q + u[:3], [u_dep[x].subs(params) for x in u[3:]], 'math')
qd_f = lambdify(q + u, [kdd[x].subs(params) for x in qd[:3]], 'math')
rng = random.Random(20261129)
for trial in range(6):
    yaw, lean, spin = rng.uniform(-3, 3), rng.uniform(-1, 1), rng.uniform(-3, 3)
    height = -params[r]*cos(lean)
    qs = [yaw, lean, spin, float(height)]
    ui = [rng.uniform(-2, 2) for _ in range(3)]
    us = ui + [float(x) for x in u_dep_f(*qs, *ui)]
    Mm = mpmath.matrix(mass(*qs, *us))
    ff = mpmath.matrix(forcing(*qs, *us))
    udot = mpmath.lu_solve(Mm, ff)
    F = force_N(*qs, *us, *[float(x) for x in udot])
    rates = qd_f(*qs, *us)
    v = v_O(*qs, *us)
    print(*[repr(float(x)) for x in [yaw, lean, spin, 0.0, 0.0, height] + list(rates) + list(v) + list(F)])
