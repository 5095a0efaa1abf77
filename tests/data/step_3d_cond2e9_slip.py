#!/usr/bin/python3
"""The slips of the 3-D step of issue 34 (cond(A) = 2e9, state b, Archard wear), at 50 digits.

Independent reference of tests/rate_problem/test_3d_conditioning.cpp ("the single slip far from
any critical load is listed"). Slip (docs/contact_3d.md, (3D.24)): P_T1 = mu x D t, t = (cos phi,
sin phi), x = P_N1, l = lambda, x u(t) + l v(t) + x l m = r with u = (mu D t, 1) + A (C_T mu D t,
0), v = A (D^-1 t, 0), m = c_w A e_N (c_w = k_a / (3 P_s)), r = DF (grazing start). Cramer's rule
on the 3 x 3 system for (x, l, y = x l) gives x, l and the condition y = x l, i.e. (3D.26); its
zeros are bracketed on a 2880-point scan and refined by mpmath.findroot. A slip needs x > 0 and
l > 0. Separation (Dw_N of A^-1 DF <= 0) and stick ((I + A S) DP = DF in the cone) are
checked too: the one solution is the slip. Run: /usr/bin/python3 tests/data/step_3d_cond2e9_slip.py (needs mpmath).
"""
import mpmath as mp
mp.mp.dps = 50
A = mp.matrix([[0.9575676186378252, 0.4094928783254124, 0.4317205031739679], [0.4094928783254124, 0.22438485805954217, -0.09819590130683155], [0.4317205031739679, -0.09819590130683155, 1.8180475243026326]])
mu, CT, ka, Ps = mp.mpf(0.26611328125), mp.mpf(0.257568359375), mp.mpf(0.9970703125), mp.mpf(0.94873046875)
al = [mp.mpf(0.21728515625), mp.mpf(0.2724609375)]
r = mp.matrix([-0.71923828125, 0.28759765625, 0.632568359375])
k = ka/(3*Ps)
m = k*A[:,2]
def uv(phi):
    t = [mp.cos(phi), mp.sin(phi)]
    Dt = [al[0]*t[0], al[1]*t[1]]
    u = mp.matrix([mu*Dt[0], mu*Dt[1], 1]) + A[:,0]*(CT*mu*Dt[0]) + A[:,1]*(CT*mu*Dt[1])
    v = A[:,0]*(t[0]/al[0]) + A[:,1]*(t[1]/al[1])
    return u, v
def det3(a,b,c): return mp.det(mp.matrix([[a[0],b[0],c[0]],[a[1],b[1],c[1]],[a[2],b[2],c[2]]]))
def h(phi):
    u,v = uv(phi)
    return det3(r,v,m)*det3(u,r,m) - det3(u,v,r)*det3(u,v,m)
def xl(phi):
    u,v = uv(phi)
    D = det3(u,v,m)
    x = det3(r,v,m)/D; l = det3(u,r,m)/D; y = det3(u,v,r)/D
    return x,l,y
n=2880
prev=None
for i in range(n+1):
    phi = -mp.pi + 2*mp.pi*i/n
    hv = h(phi)
    if prev is not None and (hv>0)!=(prev[1]>0):
        ph = mp.findroot(h, (prev[0], phi), solver='anderson')
        x,l,y = xl(ph)
        t=[mp.cos(ph), mp.sin(ph)]
        print("root phi=%s x=%s l=%s y-xl=%s PT1=(%s,%s)" % (mp.nstr(ph,17), mp.nstr(x,17), mp.nstr(l,17), mp.nstr(y-x*l,5), mp.nstr(mu*x*al[0]*t[0],10), mp.nstr(mu*x*al[1]*t[1],10)))
    prev=(phi,hv)
ev = mp.eigsy(A)[0]
print("cond", max(ev)/min(ev))
# separation: P1 = 0, Dw = A^-1 r, admissible when Dw_N <= 0; stick: (I + A S) DP = r, P_N1 >= 0,
# |D^-1 P_T1| <= mu P_N1
Dw = mp.lu_solve(A, r)
print("separation Dw_N =", mp.nstr(Dw[2], 10), "(admissible)" if Dw[2] <= 0 else "(not admissible)")
K = mp.eye(3)
for i in range(3):
    for j in range(2): K[i, j] += CT * A[i, j]
DP = mp.lu_solve(K, r)
cone = mp.sqrt((DP[0]/al[0])**2 + (DP[1]/al[1])**2) - mu*DP[2]
print("stick P_N1 =", mp.nstr(DP[2], 10), "cone excess =", mp.nstr(cone, 10),
      "(admissible)" if DP[2] >= 0 and cone <= 0 else "(not admissible)")
