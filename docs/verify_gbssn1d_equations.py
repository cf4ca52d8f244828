#!/usr/bin/env python3
# -*- coding: utf-8 -*-
"""
verify_gbssn1d_equations.py  --  symbolic verification of the spherically symmetric
generalized (covariant, "Lagrangian") BSSN equations documented in
docs/gbssn1d-equations.md, and of Brown's Eulerian volume choice beside them (V9).

Run:   python3 docs/verify_gbssn1d_equations.py  (needs Debian python3-sympy)        (about 1-3 minutes)
Needs: sympy (tested with 1.11).  The optional NRPy+ cross-check (test V2)
       runs only if the environment variable NRPY_SRC names an NRPy
       (nrpy/nrpy) source tree; it is skipped otherwise.

Conventions (same as the .md file)
  dl^2 = e^{4 phi} ( a dr^2 + r^2 b dOmega^2 ),   chi = e^{-4 phi}
  A_a = tilde A^r_r, A_b = tilde A^theta_theta (= -A_a/2), K = trace
  L  == evolved Delta^r (BSSN "Lambda-bar^r"),  hat metric = flat spherical
  ADM sign convention:  d_t gamma_ij = -2 alpha K_ij + Lie_beta gamma_ij

What is checked (each prints PASS/FAIL):
  V1  full 3D covariant (Brown) BSSN RHS in spherical coords, built from the
      general tensor equations, vs. the 1D formulas (L independent of a,b;
      A_b general and A_b=-A_a/2).
  V2  (optional) NRPy+'s own BSSN RHS expressions (Spherical reference metric,
      det(gammabar)=det(gammahat), i.e. b = a^{-1/2}) vs. the 1D formulas.
  V3  ADM equations: for arbitrary a,b,phi,K,A_a,alpha,beta (with L = Delta^r
      computed from the metric, A_b=-A_a/2) the 1D RHS reproduce
      d_t gamma_ij exactly and d_t K_ij up to the known (alpha/3) gamma_ij H
      term; Ricci components equal the directly computed ones;
      d_t Delta^r equals the chain-rule time derivative of Delta^r(a,b) up to
      a multiple of the momentum constraint; Hamiltonian and momentum
      constraints equal R+K^2-K_ijK^ij and D_j K^j_r - d_r K.
  V4  chi = e^{-4 phi} forms equal the phi forms.
  V5  Schwarzschild, isotropic, static lapse: all RHS (incl. gauge) vanish,
      H = M = G = 0, expansion vanishes at r=M/2, M_AH = M.
  V6  Stationary data with non-zero shift: Kerr-Schild (two different
      conformal splittings), Painleve-Gullstrand, and the family of maximal
      (K=0) slices of Schwarzschild in areal coordinates (Estabrook et al.
      1973; C=3 sqrt(3) M^2/4 is the trumpet), and the Baumgarte & Naculich (2007)
      maximal trumpet in isotropic coordinates (shift beta = C r/R^3):
      all field RHS vanish, constraints vanish, Theta=0 at the horizon,
      M_AH = M, Misner-Sharp mass = M.
  V7  parity / regularity: every RHS has the parity of its variable, and all
      RHS are finite at r=0 for regular (even/odd Taylor) data; the local
      flatness conditions a-b=O(r^2), A_a=O(r^2) are preserved.
  V8  Z4c with constraint damping (Sec. 17): the 1D right-hand sides equal the 3D covariant
      Z4c ones (Hilditch et al. 2013, eq. (5), in Brown's form) on a diagonal spherical metric;
      with Theta = 0 and Delta^r = Delta_gamma^r they are BSSN's, and d_t Theta = (alpha/2) H
      (so the exact data of V5, V6 are stationary); the constraint subsystem's identities
      (I1)-(I3) hold for arbitrary data.
  V9  Eulerian volume choice (sigma = 0, Sec. 18): brown_bssn_rhs_3d with sigma = 0 vs the
      1D Eulerian formulas (E1e)-(E6e) ("V1e", A_b general and A_b=-A_a/2); the sigma terms
      of the 3D RHS from the definitions (physical gamma_ij and A_ij do not depend on sigma,
      Lambda's sigma terms are the change of Delta^r(a,b) under gbar's sigma rescaling,
      d_t ln det gbar = 2 (1 - sigma) Dbar.beta); Lagrangian minus Eulerian = the sigma terms,
      equation by equation; chi form; d_t ln(a b^2) = 2 Dbar.beta; ADM consistency as in V3;
      Kerr-Schild keeps gamma_ij, K_ij but not a, b; parity and regularity as in V7.
  V10 massless scalar field (Sec. 19): the sources from T_ab, (S1)-(S2) as the Klein-Gordon
      equation for any lapse and shift, (S4)-(S6) as the ADM equations with matter, parity.
  V11 energy flux (S7): along a sphere of fixed areal radius the rates of BSSN with matter
      change the Misner-Sharp mass by -F, for any lapse, shift and matter, once the constraints
      with their sources hold (and not with j_r's sign flipped); the scalar field's form.
"""
import os
import sys
import time
import random
import sympy as sp

T0 = time.time()
r, th, vp = sp.symbols('r theta varphi', positive=True)
M = sp.symbols('M', positive=True)
XYZ = (r, th, vp)
eps = sp.symbols('epsilon')

NFAIL = 0


def report(ok, label):
    global NFAIL
    if not ok:
        NFAIL += 1
    print(('PASS  ' if ok else 'FAIL  ') + label, flush=True)


def D(f, n=1):
    return sp.diff(f, r, n)


def zero(e):
    """Exact zero test (expressions are rational after phi = log psi)."""
    e = sp.sympify(e).doit()
    if e == 0:
        return True
    try:
        z = sp.cancel(sp.together(sp.expand(e)))
        if z == 0:
            return True
    except Exception:
        pass
    z = sp.simplify(e)
    return z == 0


# ----------------------------------------------------------------------------
# 1. The 1D formulas exactly as written in gbssn1d_equations.md (phi version)
#    Arguments are sympy expressions in r.  L = evolved Delta^r.
# ----------------------------------------------------------------------------
def Delta_gamma(a, b):
    """Delta^r computed from the conformal metric (value the constraint G^r compares to)."""
    return (D(a)/(2*a) - D(b)/b + 2*(a/b - 1)/r)/a


def divbeta(a, b, beta):
    """conformal divergence  Dbar_k beta^k."""
    return D(beta) + beta*(D(a)/(2*a) + D(b)/b + 2/r)


def lap_alpha(a, b, phi, alpha):
    """physical Laplacian D^k D_k alpha."""
    return sp.exp(-4*phi)/a*(D(alpha, 2) - D(alpha)*(D(a)/(2*a) - D(b)/b - 2*D(phi) - 2/r))


def DrDr_alpha(a, b, phi, alpha):
    """mixed D^r D_r alpha (physical)."""
    return sp.exp(-4*phi)/a*(D(alpha, 2) - D(alpha)*(D(a)/(2*a) + 2*D(phi)))


def DthDth_alpha(a, b, phi, alpha):
    """mixed D^theta D_theta alpha (physical)."""
    return sp.exp(-4*phi)/a*D(alpha)*(1/r + D(b)/(2*b) + 2*D(phi))


def DrDr_minus_DthDth_alpha(a, b, phi, alpha):
    """D^r D_r alpha - D^theta D_theta alpha  (the combination needed by the A_a equation)."""
    return sp.exp(-4*phi)/a*(D(alpha, 2) - D(alpha)*(D(a)/(2*a) + D(b)/(2*b) + 4*D(phi) + 1/r))


def Ricci_rr(a, b, phi, L):
    """mixed physical R^r_r; L (evolved Delta^r) appears only as d_r L."""
    bar = (D(L) + (-D(a, 2)/(2*a) + (D(a)/a)**2 - D(a)*D(b)/(2*a*b) - (D(b)/b)**2/2
                   - D(a)/(r*a) + 2*D(b)/(r*b)*(a/b - 1) + 2*(a/b - 1)/r**2)/a)
    conf = (-4*D(phi, 2) + 2*D(phi)*(D(a)/a - D(b)/b - 2/r))/a
    return sp.exp(-4*phi)*(bar + conf)


def Ricci_thth(a, b, phi, L):
    """mixed physical R^theta_theta; L (evolved Delta^r) appears undifferentiated as L/r."""
    bar = (L/r + (-D(b, 2)/(2*b) + D(a)*D(b)/(4*a*b) - D(b)/(r*b) + (1 - a/b)/r**2)/a)
    conf = (-2*D(phi, 2) - 4*D(phi)**2 + D(phi)*(D(a)/a - 3*D(b)/b - 6/r))/a
    return sp.exp(-4*phi)*(bar + conf)


def Ricci_scalar_metric(a, b, phi):
    """physical R computed purely from a, b, phi (no Delta^r) -- for diagnostics."""
    Rbar = (-2*D(b, 2)/b + (D(b)/b)**2/2 + D(a)/a*(D(b)/b + 2/r) - 6*D(b)/(r*b)
            + 2*(a/b - 1)/r**2)/a
    return sp.exp(-4*phi)*(Rbar - 8/a*(D(phi, 2) + D(phi)**2 + D(phi)*(2/r + D(b)/b - D(a)/(2*a))))


def rhs_1d(a, b, phi, K, Aa, Ab, L, alpha, beta):
    """BSSN field RHS (vacuum, Lagrangian choice).  Returns dict."""
    dvb = divbeta(a, b, beta)
    lap = lap_alpha(a, b, phi, alpha)
    Rrr = Ricci_rr(a, b, phi, L)
    Rtt = Ricci_thth(a, b, phi, L)
    R = Rrr + 2*Rtt
    out = {}
    out['phi'] = beta*D(phi) + (dvb - alpha*K)/6
    out['a'] = beta*D(a) + 2*a*D(beta) - sp.Rational(2, 3)*a*dvb - 2*alpha*a*Aa
    out['b'] = beta*D(b) + 2*b*beta/r - sp.Rational(2, 3)*b*dvb - 2*alpha*b*Ab
    out['K'] = beta*D(K) - lap + alpha*(Aa**2 + 2*Ab**2 + K**2/3)
    out['Aa'] = (beta*D(Aa) - (DrDr_alpha(a, b, phi, alpha) - lap/3)
                 + alpha*(Rrr - R/3) + alpha*K*Aa)
    out['Ab'] = (beta*D(Ab) - (DthDth_alpha(a, b, phi, alpha) - lap/3)
                 + alpha*(Rtt - R/3) + alpha*K*Ab)
    out['L'] = (beta*D(L) - L*D(beta)
                + D(beta, 2)/a + 2*D(beta/r)/b
                + sp.Rational(2, 3)*Delta_gamma(a, b)*dvb + D(dvb)/(3*a)
                - 2*Aa/a*(D(alpha) - 6*alpha*D(phi))
                + alpha/a*(Aa*D(a)/a - 2*Ab*(D(b)/b + 2*(1 - a/b)/r))
                - sp.Rational(4, 3)*alpha*D(K)/a)
    return out


def rhs_Aa_compact(a, b, phi, K, Aa, L, alpha, beta):
    """equivalent trace-free form used in the .md:  (2/3)[...] differences."""
    return (beta*D(Aa) - sp.Rational(2, 3)*(DrDr_alpha(a, b, phi, alpha) - DthDth_alpha(a, b, phi, alpha))
            + sp.Rational(2, 3)*alpha*(Ricci_rr(a, b, phi, L) - Ricci_thth(a, b, phi, L)) + alpha*K*Aa)


def rhs_L_traceless(a, b, phi, K, Aa, L, alpha, beta):
    """Delta^r RHS with A_b=-A_a/2 already substituted (as written in the .md)."""
    dvb = divbeta(a, b, beta)
    return (beta*D(L) - L*D(beta) + D(beta, 2)/a + 2*D(beta/r)/b
            + sp.Rational(2, 3)*Delta_gamma(a, b)*dvb + D(dvb)/(3*a)
            - 2*Aa/a*(D(alpha) - 6*alpha*D(phi))
            + alpha*Aa/a*(D(a)/a + D(b)/b + 2*(1 - a/b)/r)
            - sp.Rational(4, 3)*alpha*D(K)/a)


def rhs_1d_eulerian(a, b, phi, K, Aa, Ab, L, alpha, beta):
    """BSSN field RHS (vacuum), Brown's Eulerian choice sigma = 0 (Sec. 18, (E1e)-(E6e)):
    no -(2/3) Dbar.beta terms in d_t phi, a, b and no (2/3) Delta_gamma^r Dbar.beta
    + (1/(3a)) (Dbar.beta)' in d_t Delta^r.  K, A_a, A_b: (E4), (E5), (E5b) unchanged."""
    o = rhs_1d(a, b, phi, K, Aa, Ab, L, alpha, beta)
    out = {'K': o['K'], 'Aa': o['Aa'], 'Ab': o['Ab']}
    out['phi'] = beta*D(phi) - alpha*K/6
    out['a'] = beta*D(a) + 2*a*D(beta) - 2*alpha*a*Aa
    out['b'] = beta*D(b) + 2*b*beta/r - 2*alpha*b*Ab
    out['L'] = (beta*D(L) - L*D(beta)
                + D(beta, 2)/a + 2*D(beta/r)/b
                - 2*Aa/a*(D(alpha) - 6*alpha*D(phi))
                + alpha/a*(Aa*D(a)/a - 2*Ab*(D(b)/b + 2*(1 - a/b)/r))
                - sp.Rational(4, 3)*alpha*D(K)/a)
    return out


def rhs_L_eulerian(a, b, phi, K, Aa, L, alpha, beta):
    """Delta^r RHS of the Eulerian choice with A_b = -A_a/2 substituted ((E6e), traceless form)."""
    return (beta*D(L) - L*D(beta) + D(beta, 2)/a + 2*D(beta/r)/b
            - 2*Aa/a*(D(alpha) - 6*alpha*D(phi))
            + alpha*Aa/a*(D(a)/a + D(b)/b + 2*(1 - a/b)/r)
            - sp.Rational(4, 3)*alpha*D(K)/a)


def gauge_rhs(K, alpha, beta, Bv, L, rhsL, eta, advect=True):
    out = {'alpha': beta*D(alpha) - 2*alpha*K,
           'beta': sp.Rational(3, 4)*Bv + (beta*D(beta) if advect else 0),
           'B': rhsL - eta*Bv + ((beta*D(Bv) - beta*D(L)) if advect else 0)}
    return out


def hamiltonian(a, b, phi, K, Aa, Ab, L):
    return Ricci_rr(a, b, phi, L) + 2*Ricci_thth(a, b, phi, L) - (Aa**2 + 2*Ab**2) + sp.Rational(2, 3)*K**2


def momentum(a, b, phi, K, Aa, Ab):
    """M_r = D_j K^j_r - d_r K  (vacuum: = 0)."""
    return D(Aa) - sp.Rational(2, 3)*D(K) + (Aa - Ab)*(2/r + D(b)/b + 4*D(phi))


def gconstraint(a, b, L):
    return L - Delta_gamma(a, b)


def expansion(a, b, phi, K, Aa):
    """outgoing null expansion of the sphere r=const (A_b=-A_a/2 used)."""
    return sp.exp(-2*phi)/sp.sqrt(a)*(2/r + D(b)/b + 4*D(phi)) + Aa - sp.Rational(2, 3)*K


def areal_radius(b, phi):
    return r*sp.exp(2*phi)*sp.sqrt(b)


def misner_sharp(a, b, phi, K, Ab):
    R = areal_radius(b, phi)
    Ktt = Ab + K/3
    return R/2*(1 - D(R)**2/(sp.exp(4*phi)*a) + R**2*Ktt**2)


def rhs_z4c_1d(a, b, phi, Kh, Th, Aa, L, alpha, beta, k1, k2):
    """Z4c field RHS (Sec. 17), A_b = -A_a/2: BSSN's with K = K-hat + 2 Theta wherever K is
    undifferentiated (Z1), d_t K-hat advecting K-hat and damped (Z2), Theta's equation (Z3), and
    Delta^r's with -(2/3)(alpha/a) d_r(2 K-hat + Theta) and the damping -2 alpha kappa1 G^r (Z4)."""
    K = Kh + 2*Th
    o = rhs_1d(a, b, phi, K, Aa, -Aa/2, L, alpha, beta)
    R = Ricci_rr(a, b, phi, L) + 2*Ricci_thth(a, b, phi, L)
    out = {'phi': o['phi'], 'a': o['a'], 'b': o['b'], 'Aa': o['Aa']}
    out['K'] = (beta*D(Kh) - lap_alpha(a, b, phi, alpha) + alpha*(sp.Rational(3, 2)*Aa**2 + K**2/3)
                + alpha*k1*(1 - k2)*Th)
    out['L'] = (o['L'] + sp.Rational(4, 3)*alpha*D(K)/a - sp.Rational(2, 3)*alpha*D(2*Kh + Th)/a
                - 2*alpha*k1*(L - Delta_gamma(a, b)))
    out['Theta'] = (beta*D(Th) + alpha/2*(R - sp.Rational(3, 2)*Aa**2 + sp.Rational(2, 3)*K**2)
                    - alpha*k1*(2 + k2)*Th)
    return out


# chi versions (as written in the .md)
def rhs_chi(a, b, chi, K, alpha, beta):
    return beta*D(chi) + sp.Rational(2, 3)*chi*(alpha*K - divbeta(a, b, beta))


def rhs_chi_eulerian(a, b, chi, K, alpha, beta):
    """(E1e) in chi form: d_t chi = beta chi' + (2/3) chi alpha K (a, b unused: no Dbar.beta)."""
    return beta*D(chi) + sp.Rational(2, 3)*chi*alpha*K


def lap_alpha_chi(a, b, chi, alpha):
    return chi/a*(D(alpha, 2) - D(alpha)*(D(a)/(2*a) - D(b)/b - 2/r) - D(alpha)*D(chi)/(2*chi))


def DrDr_minus_DthDth_chi(a, b, chi, alpha):
    return chi/a*(D(alpha, 2) - D(alpha)*(D(a)/(2*a) + D(b)/(2*b) + 1/r) + D(alpha)*D(chi)/chi)


def Ricci_rr_chi(a, b, chi, L):
    bar = (D(L) + (-D(a, 2)/(2*a) + (D(a)/a)**2 - D(a)*D(b)/(2*a*b) - (D(b)/b)**2/2
                   - D(a)/(r*a) + 2*D(b)/(r*b)*(a/b - 1) + 2*(a/b - 1)/r**2)/a)
    conf = (D(chi, 2)/chi - (D(chi)/chi)**2 - D(chi)/(2*chi)*(D(a)/a - D(b)/b - 2/r))/a
    return chi*(bar + conf)


def Ricci_thth_chi(a, b, chi, L):
    bar = (L/r + (-D(b, 2)/(2*b) + D(a)*D(b)/(4*a*b) - D(b)/(r*b) + (1 - a/b)/r**2)/a)
    conf = (D(chi, 2)/(2*chi) - sp.Rational(3, 4)*(D(chi)/chi)**2
            - D(chi)/(4*chi)*(D(a)/a - 3*D(b)/b - 6/r))/a
    return chi*(bar + conf)


def Ricci_scalar_metric_chi(a, b, chi):
    Rbar = (-2*D(b, 2)/b + (D(b)/b)**2/2 + D(a)/a*(D(b)/b + 2/r) - 6*D(b)/(r*b)
            + 2*(a/b - 1)/r**2)/a
    return chi*(Rbar + (2*D(chi, 2)/chi - sp.Rational(5, 2)*(D(chi)/chi)**2
                        + 2*D(chi)/chi*(2/r + D(b)/b - D(a)/(2*a)))/a)


def DrDr_alpha_chi(a, b, chi, alpha):
    return chi/a*(D(alpha, 2) - D(alpha)*(D(a)/(2*a) - D(chi)/(2*chi)))


def DthDth_alpha_chi(a, b, chi, alpha):
    return chi/a*D(alpha)*(1/r + D(b)/(2*b) - D(chi)/(2*chi))


def divbeta_prime(a, b, beta):
    """explicit d_r (Dbar_k beta^k)."""
    return (D(beta, 2) + D(beta)*(D(a)/(2*a) + D(b)/b + 2/r)
            + beta*(D(a, 2)/(2*a) - D(a)**2/(2*a**2) + D(b, 2)/b - D(b)**2/b**2 - 2/r**2))


def rhs_L_chi_piece(a, Aa, alpha, chi):
    """the only chi-dependent term of the Delta^r RHS."""
    return -2*Aa/a*(D(alpha) + sp.Rational(3, 2)*alpha*D(chi)/chi)


def momentum_chi(a, b, chi, K, Aa):
    return D(Aa) - sp.Rational(2, 3)*D(K) + sp.Rational(3, 2)*Aa*(2/r + D(b)/b - D(chi)/chi)


def expansion_chi(a, b, chi, K, Aa):
    return sp.sqrt(chi/a)*(2/r + D(b)/b - D(chi)/chi) + Aa - sp.Rational(2, 3)*K


# the massless scalar field (Sec. 19)
def scalar_sources(a, chi, Phi, Pi):
    """(S3): rho, j_r, S^r_r, S^theta_theta and S of T_ab = d_a Phi d_b Phi - (1/2) g_ab (dPhi)^2,
    with Pi = n^a d_a Phi (chi form)."""
    q = chi*D(Phi)**2/a
    return {'rho': (Pi**2 + q)/2, 'jr': -Pi*D(Phi), 'Sa': (Pi**2 + q)/2, 'Sb': (Pi**2 - q)/2,
            'S': sp.Rational(3, 2)*Pi**2 - q/2}


def scalar_rhs(a, b, chi, K, alpha, beta, Phi, Pi):
    """(S1)-(S2): d_t Phi and d_t Pi, Pi = n^a d_a Phi = (d_t Phi - beta Phi')/alpha."""
    return {'Phi': beta*D(Phi) + alpha*Pi,
            'Pi': beta*D(Pi) + alpha*K*Pi
            + chi/a*(alpha*D(Phi, 2) + D(Phi)*(D(alpha) + alpha*(2/r + D(b)/b - D(a)/(2*a)
                                                                 - D(chi)/(2*chi))))}


def matter_terms(a, alpha, src):
    """(S4)-(S6): the stress-energy's terms in d_t K (Z4c: d_t K-hat), d_t A_a, d_t Delta^r and
    d_t Theta (Z4c), and in H and M_r (each constraint minus its source vanishes)."""
    return {'K': 4*sp.pi*alpha*(src['rho'] + src['S']),
            'Aa': -8*sp.pi*alpha*(src['Sa'] - src['S']/3),
            'L': -16*sp.pi*alpha*src['jr']/a,
            'Theta': -8*sp.pi*alpha*src['rho'],
            'H': -16*sp.pi*src['rho'], 'M': -8*sp.pi*src['jr']}


# ----------------------------------------------------------------------------
# 2. Independent 3D machinery (full tensor index loops, theta-dependence kept)
# ----------------------------------------------------------------------------
def pd(f, k):
    return sp.diff(f, XYZ[k])


def christoffel(g):
    gi = g.inv()
    return [[[sp.simplify(sum(gi[i, m]*(pd(g[m, j], k) + pd(g[m, k], j) - pd(g[j, k], m))
                              for m in range(3))/2)
              for k in range(3)] for j in range(3)] for i in range(3)]


def ricci_direct(g):
    G = christoffel(g)
    R = sp.zeros(3, 3)
    for i in range(3):
        for j in range(3):
            e = 0
            for k in range(3):
                e += pd(G[k][i][j], k) - pd(G[k][i][k], j)
                for l in range(3):
                    e += G[k][k][l]*G[l][i][j] - G[k][j][l]*G[l][i][k]
            R[i, j] = e
    return R, G


def cov_hess_scalar(f, G):
    return sp.Matrix(3, 3, lambda i, j: pd(pd(f, i), j) - sum(G[k][i][j]*pd(f, k) for k in range(3)))


def lie_cov2(T, beta_u):
    return sp.Matrix(3, 3, lambda i, j: sum(beta_u[k]*pd(T[i, j], k) + T[k, j]*pd(beta_u[k], i)
                                            + T[i, k]*pd(beta_u[k], j) for k in range(3)))


def brown_bssn_rhs_3d(gb, gh, Abar, phi, K, Lam, alpha, beta_u, sigma=1):
    """Covariant BSSN (Brown 2009), vacuum, full 3D index sums.  sigma = 1 is the Lagrangian
    choice (d_t det gbar = 0), sigma = 0 the Eulerian one (d_t ln det gbar = 2 Dbar_k beta^k).

    Where sigma enters (derived here from the definitions, not copied): the generalized
        d_t gbar_ij = L_beta gbar_ij - (2/3) sigma gbar_ij Dbar_k beta^k - 2 alpha Abar_ij
    has the trace  d_t ln det gbar = gbar^ij d_t gbar_ij = 2 (1 - sigma) Dbar_k beta^k
    (gbar^ij L_beta gbar_ij = 2 Dbar_k beta^k, Abar trace-free).  Its sigma term is a
    conformal rescaling d_t gbar_ij = 2 w gbar_ij with w = -(sigma/3) Dbar_k beta^k, and
      * phi = (1/12) ln(gamma/gbar):  d_t ln gamma = 2 D_k beta^k - 2 alpha K and
        D_k beta^k - Dbar_k beta^k = 6 beta^k d_k phi give
        d_t phi = beta^k d_k phi + (sigma/6) Dbar_k beta^k - alpha K/6;
      * Abar_ij = e^{-4 phi} (K_ij - gamma_ij K/3): the physical part does not see sigma, so
        its only sigma term is -4 (d_t phi) Abar_ij's  -(2/3) sigma Abar_ij Dbar_k beta^k;
      * Lambda^i = Delta^i = gbar^jk (Gbar^i_jk - Ghat^i_jk): under the rescaling
        d_t gbar^jk = -2 w gbar^jk and gbar^jk d_t Gbar^i_jk = -gbar^ij d_j w, so the sigma
        terms are  (2/3) sigma Delta^i Dbar_k beta^k + (1/3) sigma gbar^ij d_j(Dbar_k beta^k)
        (Delta^i computed from the metric, as in the Lagrangian equation).
    Everything else (K, the physical Ricci tensor, D_i D_j alpha, the Abar and alpha terms of
    Lambda's equation) does not depend on sigma."""
    gbi = gb.inv()
    Gb = christoffel(gb)
    Gh = christoffel(gh)
    Dl = [[[Gb[i][j][k] - Gh[i][j][k] for k in range(3)] for j in range(3)] for i in range(3)]
    Du = [sum(gbi[j, k]*Dl[i][j][k] for j in range(3) for k in range(3)) for i in range(3)]
    DL = [[[sum(gb[i, l]*Dl[l][j][k] for l in range(3)) for k in range(3)] for j in range(3)] for i in range(3)]
    divb = sum(pd(beta_u[k], k) for k in range(3)) + sum(Gb[k][k][m]*beta_u[m] for k in range(3) for m in range(3))
    # physical metric quantities
    e4p = sp.exp(4*phi)
    g = e4p*gb
    gi = g.inv()
    Rphys_direct, G = ricci_direct(g)
    DDalpha = cov_hess_scalar(alpha, G)
    lap = sum(gi[i, j]*DDalpha[i, j] for i in range(3) for j in range(3))
    # conformal Ricci in Brown's form with the evolved Lambda
    T = [[[pd(gb[i, j], k) - sum(Gh[m][k][i]*gb[m, j] + Gh[m][k][j]*gb[i, m] for m in range(3))
           for k in range(3)] for j in range(3)] for i in range(3)]

    def DDgb(i, j, k, l):  # hat D_l hat D_k gbar_ij
        return pd(T[i][j][k], l) - sum(Gh[m][l][i]*T[m][j][k] + Gh[m][l][j]*T[i][m][k]
                                       + Gh[m][l][k]*T[i][j][m] for m in range(3))
    DhLam = [[pd(Lam[k], j) + sum(Gh[k][j][m]*Lam[m] for m in range(3)) for j in range(3)] for k in range(3)]
    Rbar = sp.zeros(3, 3)
    for i in range(3):
        for j in range(3):
            e = -sp.Rational(1, 2)*sum(gbi[k, l]*DDgb(i, j, k, l) for k in range(3) for l in range(3))
            e += sp.Rational(1, 2)*sum(gb[k, i]*DhLam[k][j] + gb[k, j]*DhLam[k][i] for k in range(3))
            e += sp.Rational(1, 2)*sum(Du[k]*(DL[i][j][k] + DL[j][i][k]) for k in range(3))
            e += sum(gbi[k, l]*(Dl[m][k][i]*DL[j][m][l] + Dl[m][k][j]*DL[i][m][l] + Dl[m][i][k]*DL[m][j][l])
                     for k in range(3) for l in range(3) for m in range(3))
            Rbar[i, j] = e
    DDphi_bar = cov_hess_scalar(phi, Gb)
    lapphi_bar = sum(gbi[i, j]*DDphi_bar[i, j] for i in range(3) for j in range(3))
    dphi2 = sum(gbi[i, j]*pd(phi, i)*pd(phi, j) for i in range(3) for j in range(3))
    Rphi = sp.Matrix(3, 3, lambda i, j: -2*DDphi_bar[i, j] - 2*gb[i, j]*lapphi_bar
                     + 4*pd(phi, i)*pd(phi, j) - 4*gb[i, j]*dphi2)
    Rij = Rbar + Rphi
    Aud = gbi*Abar
    Auu = gbi*Abar*gbi
    AA = sum(Abar[i, j]*Auu[i, j] for i in range(3) for j in range(3))
    out = {}
    out['gb'] = lie_cov2(gb, beta_u) - sp.Rational(2, 3)*sigma*gb*divb - 2*alpha*Abar
    out['phi'] = sum(beta_u[k]*pd(phi, k) for k in range(3)) + (sigma*divb - alpha*K)/6
    out['K'] = sum(beta_u[k]*pd(K, k) for k in range(3)) - lap + alpha*(AA + K**2/3)
    S = -DDalpha + alpha*Rij
    trS = sum(gi[i, j]*S[i, j] for i in range(3) for j in range(3))
    STF = S - g*trS/3
    out['Abar'] = (lie_cov2(Abar, beta_u) - sp.Rational(2, 3)*sigma*Abar*divb - 2*alpha*Abar*Aud
                   + alpha*K*Abar + STF/e4p)
    # Lambda equation
    V = [[pd(beta_u[i], k) + sum(Gh[i][k][m]*beta_u[m] for m in range(3)) for k in range(3)] for i in range(3)]
    DDb = [sum(gbi[j, k]*(pd(V[i][k], j) + sum(Gh[i][j][m]*V[m][k] - Gh[m][j][k]*V[i][m] for m in range(3)))
               for j in range(3) for k in range(3)) for i in range(3)]
    Lrhs = []
    for i in range(3):
        e = sum(beta_u[j]*pd(Lam[i], j) - Lam[j]*pd(beta_u[i], j) for j in range(3))
        e += DDb[i] + sigma*(sp.Rational(2, 3)*Du[i]*divb + sp.Rational(1, 3)*sum(gbi[i, j]*pd(divb, j) for j in range(3)))
        e += -2*sum(Auu[i, j]*(pd(alpha, j) - 6*alpha*pd(phi, j)) for j in range(3))
        e += 2*alpha*sum(Auu[j, k]*Dl[i][j][k] for j in range(3) for k in range(3))
        e += -sp.Rational(4, 3)*alpha*sum(gbi[i, j]*pd(K, j) for j in range(3))
        Lrhs.append(e)
    out['L'] = Lrhs
    out['Rij'] = Rij
    out['Rphys_direct'] = Rphys_direct
    out['Delta_u'] = Du
    return out


def brown_z4c_rhs_3d(gb, gh, Abar, phi, Kh, Th, Lam, alpha, beta_u, k1, k2):
    """Z4c (Bernuzzi & Hilditch 2010; Hilditch et al. 2013, eq. (5)) in the covariant form of
    brown_bssn_rhs_3d, full 3D index sums: the BSSN equations with K = K-hat + 2 Theta, then in
    tensor form d_t K-hat's advection of K-hat and its damping alpha kappa1 (1 - kappa2) Theta,
    Lambda's -(2/3) alpha gbar^ij d_j(2 K-hat + Theta) in place of -(4/3) alpha gbar^ij d_j K and
    its damping -2 alpha kappa1 (Lambda^i - Delta^i), and
    d_t Theta = beta^k d_k Theta + (alpha/2)(R - Abar_ij Abar^ij + (2/3) K^2)
                - alpha kappa1 (2 + kappa2) Theta, R from R_ij with the evolved Lambda."""
    K = Kh + 2*Th
    out = brown_bssn_rhs_3d(gb, gh, Abar, phi, K, Lam, alpha, beta_u)
    gbi = gb.inv()
    Auu = gbi*Abar*gbi
    AA = sum(Abar[i, j]*Auu[i, j] for i in range(3) for j in range(3))
    adv = lambda f: sum(beta_u[k]*pd(f, k) for k in range(3))
    out['K'] = out['K'] - adv(2*Th) + alpha*k1*(1 - k2)*Th
    out['L'] = [out['L'][i]
                + sum(gbi[i, j]*(sp.Rational(4, 3)*alpha*pd(K, j)
                                 - sp.Rational(2, 3)*alpha*pd(2*Kh + Th, j)) for j in range(3))
                - 2*alpha*k1*(Lam[i] - out['Delta_u'][i]) for i in range(3)]
    Rscalar = sp.exp(-4*phi)*sum(gbi[i, j]*out['Rij'][i, j] for i in range(3) for j in range(3))
    out['Theta'] = adv(Th) + alpha/2*(Rscalar - AA + sp.Rational(2, 3)*K**2) - alpha*k1*(2 + k2)*Th
    return out


# generic functions of r
fa, fb, fpsi, fK, fAa, fAb, fL, fal, fbe = [sp.Function(n)(r) for n in
                                             ['a', 'b', 'psi', 'K', 'A_a', 'A_b', 'L', 'alpha', 'beta']]
fphi = sp.log(fpsi)          # phi = log psi makes every expression rational


def sph_diag(x, y):
    return sp.diag(x, r**2*y, r**2*y*sp.sin(th)**2)


# ============================================================================
print('=== V1: full 3D covariant BSSN RHS vs 1D formulas ===', flush=True)
gb = sph_diag(fa, fb)
gh = sph_diag(1, 1)
for label, Ab_ in [('A_b general', fAb), ('A_b=-A_a/2', -fAa/2)]:
    Abar = sp.diag(fa*fAa, r**2*fb*Ab_, r**2*fb*Ab_*sp.sin(th)**2)
    t = time.time()
    R3 = brown_bssn_rhs_3d(gb, gh, Abar, fphi, fK, [fL, 0, 0], fal, [fbe, 0, 0])
    o1 = rhs_1d(fa, fb, fphi, fK, fAa, Ab_, fL, fal, fbe)
    # structure: off-diagonals zero, phi-phi = sin^2 theta-theta
    ok = all(zero(R3['gb'][i, j]) and zero(R3['Abar'][i, j]) for i in range(3) for j in range(3) if i != j)
    ok = ok and zero(R3['gb'][2, 2] - sp.sin(th)**2*R3['gb'][1, 1]) and zero(R3['Abar'][2, 2] - sp.sin(th)**2*R3['Abar'][1, 1])
    ok = ok and zero(R3['L'][1]) and zero(R3['L'][2])
    report(ok, f'[{label}] 3D RHS is diagonal, spherically symmetric, Lambda^theta=Lambda^phi=0')
    rhs_a3 = R3['gb'][0, 0]
    rhs_b3 = R3['gb'][1, 1]/r**2
    rhs_Aa3 = (R3['Abar'][0, 0] - fAa*rhs_a3)/fa
    rhs_Ab3 = (R3['Abar'][1, 1]/r**2 - Ab_*rhs_b3)/fb
    report(zero(R3['phi'] - o1['phi']), f'[{label}] d_t phi')
    report(zero(rhs_a3 - o1['a']), f'[{label}] d_t a')
    report(zero(rhs_b3 - o1['b']), f'[{label}] d_t b')
    report(zero(R3['K'] - o1['K']), f'[{label}] d_t K')
    report(zero(rhs_Aa3 - o1['Aa']), f'[{label}] d_t A_a')
    report(zero(rhs_Ab3 - o1['Ab']), f'[{label}] d_t A_b')
    report(zero(R3['L'][0] - o1['L']), f'[{label}] d_t Delta^r (evolved, Brown form)')
    Rrr3 = R3['Rij'][0, 0]*sp.exp(-4*fphi)/fa
    Rtt3 = R3['Rij'][1, 1]*sp.exp(-4*fphi)/(r**2*fb)
    report(zero(Rrr3 - Ricci_rr(fa, fb, fphi, fL)), f'[{label}] R^r_r (Brown form, evolved Delta^r)')
    report(zero(Rtt3 - Ricci_thth(fa, fb, fphi, fL)), f'[{label}] R^theta_theta (Brown form, evolved Delta^r)')
    if Ab_ is not fAb:
        report(zero(rhs_Aa3 - rhs_Aa_compact(fa, fb, fphi, fK, fAa, fL, fal, fbe)),
               f'[{label}] compact d_t A_a = (2/3)[...] form')
        report(zero(R3['L'][0] - rhs_L_traceless(fa, fb, fphi, fK, fAa, fL, fal, fbe)),
               f'[{label}] d_t Delta^r, traceless-substituted form')
        report(zero(rhs_Ab3 + rhs_Aa3/2), f'[{label}] d_t A_b = -d_t A_a/2 (trace preserved)')
    print(f'      ({time.time()-t:.1f}s)', flush=True)

report(zero(divbeta_prime(fa, fb, fbe) - D(divbeta(fa, fb, fbe))), 'explicit d_r(Dbar_k beta^k)')
oo = rhs_1d(fa, fb, fphi, fK, fAa, fAb, fL, fal, fbe)
report(zero(oo['a']/fa + 2*oo['b']/fb + 2*fal*(fAa + 2*fAb)), 'd_t ln(a b^2) = -2 alpha (A_a + 2 A_b)  (= 0 when trace-free: a b^2 frozen)')
# Delta^r computed from metric
report(zero(R3['Delta_u'][0] - Delta_gamma(fa, fb)), 'Delta^r(a,b) = gbar^jk (Gbar^r_jk - Ghat^r_jk)')
report(zero(divbeta(fa, fb, fbe) - (D(fbe) + fbe*D(sp.log(sp.sqrt(fa)*fb*r**2)))), 'Dbar_k beta^k = (1/sqrt(gbar)) d_r(sqrt(gbar) beta)')

# ============================================================================
print('=== V2: NRPy+ (independent implementation) cross-check ===', flush=True)


def nrpy_check():
    src = os.environ.get('NRPY_SRC', '')
    if not src or not os.path.isdir(os.path.join(src, 'nrpy')):
        print('SKIP  NRPy+ tree not given (set NRPY_SRC)')
        return
    sys.path.insert(0, src)
    try:
        import nrpy.params as par
        from nrpy.equations.general_relativity.BSSN_RHSs import BSSN_RHSs
        from nrpy.equations.general_relativity.BSSN_quantities import BSSN_quantities
    except Exception as exc:  # pragma: no cover
        print('SKIP  NRPy+ import failed:', exc)
        return
    import io
    import contextlib
    par.set_parval_from_str('EvolvedConformalFactor_cf', 'phi')
    with contextlib.redirect_stdout(io.StringIO()):
        Rn = BSSN_RHSs['Spherical']
    # NRPy assumes det(gammabar) = det(gammahat)  ->  a b^2 = 1  ->  b = a^{-1/2}
    A_ = fa
    B_ = 1/sp.sqrt(fa)
    phi_ = fphi
    fields = {  # NRPy gridfunction -> function of r   (Spherical rescaling)
        'hDD00': A_ - 1, 'hDD11': B_ - 1, 'hDD22': B_ - 1,
        'hDD01': 0, 'hDD02': 0, 'hDD12': 0,
        'aDD00': A_*fAa, 'aDD11': B_*(-fAa/2), 'aDD22': B_*(-fAa/2),
        'aDD01': 0, 'aDD02': 0, 'aDD12': 0,
        'lambdaU0': fL, 'lambdaU1': 0, 'lambdaU2': 0,
        'vetU0': fbe, 'vetU1': 0, 'vetU2': 0,
        'betU0': 0, 'betU1': 0, 'betU2': 0,
        'cf': phi_, 'trK': fK, 'alpha': fal}
    import re

    def sub_symbol(name):
        m = re.match(r'^(.*?)_(dupD|dD|dDD|dKOD)(\d+)$', name)
        if not m:
            return fields[name]
        base, kind, idx = m.groups()
        if base in ('cf', 'trK', 'alpha'):
            comp, der = '', idx
        elif base in ('lambdaU', 'vetU', 'betU'):
            comp, der = idx[0], idx[1:]
        else:
            comp, der = idx[:2], idx[2:]
        f = fields[base + comp]
        if any(c != '0' for c in der):
            return 0
        return sp.diff(f, r, len(der))

    def to_fun(expr):
        expr = sp.sympify(expr)
        reps = {}
        for s in expr.free_symbols:
            n = str(s)
            if n == 'xx0':
                reps[s] = r
            elif n == 'xx1':
                reps[s] = th
            elif n == 'xx2':
                reps[s] = vp
            else:
                reps[s] = sub_symbol(n)
        return expr.xreplace(reps)
    o1 = rhs_1d(A_, B_, phi_, fK, fAa, -fAa/2, fL, fal, fbe)
    d = Rn.BSSN_RHSs_varname_to_expr_dict
    rhs_a_n = to_fun(d['h_rhsDD00'])
    rhs_b_n = to_fun(d['h_rhsDD11'])
    rhs_Aa_n = (to_fun(d['a_rhsDD00']) - fAa*rhs_a_n)/A_
    rhs_Ab_n = (to_fun(d['a_rhsDD11']) - (-fAa/2)*rhs_b_n)/B_
    report(zero(to_fun(d['cf_rhs']) - o1['phi']), 'NRPy d_t phi')
    report(zero(rhs_a_n - o1['a']), 'NRPy d_t a')
    report(zero(rhs_b_n - o1['b']), 'NRPy d_t b')
    report(zero(to_fun(d['trK_rhs']) - o1['K']), 'NRPy d_t K')
    report(zero(rhs_Aa_n - o1['Aa']), 'NRPy d_t A_a')
    report(zero(rhs_Ab_n - o1['Ab']), 'NRPy d_t A_b')
    report(zero(to_fun(d['lambda_rhsU0']) - o1['L']), 'NRPy d_t Delta^r')
    ok = all(zero(to_fun(d[k])) for k in ['h_rhsDD01', 'h_rhsDD02', 'h_rhsDD12', 'a_rhsDD01',
                                          'a_rhsDD02', 'a_rhsDD12', 'lambda_rhsU1', 'lambda_rhsU2'])
    ok = ok and zero(to_fun(d['h_rhsDD22']) - rhs_b_n) and zero(to_fun(d['a_rhsDD22']) - to_fun(d['a_rhsDD11']))
    report(ok, 'NRPy off-diagonal / angular components consistent with spherical symmetry')


t = time.time()
nrpy_check()
print(f'      ({time.time()-t:.1f}s)', flush=True)

# ============================================================================
print('=== V3: consistency with the ADM equations (arbitrary data) ===', flush=True)
t = time.time()
Lg = Delta_gamma(fa, fb)
o = rhs_1d(fa, fb, fphi, fK, fAa, -fAa/2, Lg, fal, fbe)
# physical metric and K_ij in 3D
g = sp.exp(4*fphi)*sph_diag(fa, fb)
Kud_rr = fAa + fK/3
Kud_tt = -fAa/2 + fK/3
Kdd = sp.diag(g[0, 0]*Kud_rr, g[1, 1]*Kud_tt, g[2, 2]*Kud_tt)
gi = g.inv()
Rdir, G = ricci_direct(g)
DDal = cov_hess_scalar(fal, G)
beta_u = [fbe, 0, 0]
Kmix = gi*Kdd
trK = sum(Kmix[i, i] for i in range(3))
KK = sum((Kmix*Kmix)[i, i] for i in range(3))
adm_g = -2*fal*Kdd + lie_cov2(g, beta_u)
adm_K = -DDal + fal*(Rdir - 2*Kdd*Kmix + trK*Kdd) + lie_cov2(Kdd, beta_u)
Hdir = sum((gi*Rdir)[i, i] for i in range(3)) + trK**2 - KK
report(zero(trK - fK), 'trace of K_ij built from (A_a, A_b=-A_a/2, K) is K')
# time derivatives implied by the 1D BSSN RHS (chain rule through epsilon)
sub_t = {fa: fa + eps*o['a'], fb: fb + eps*o['b'], fpsi: fpsi*sp.exp(eps*o['phi']),
         fK: fK + eps*o['K'], fAa: fAa + eps*o['Aa']}


def ddt(expr):
    # xreplace is a simultaneous substitution; doit() evaluates d/dr of the perturbed fields
    return sp.diff(expr.xreplace(sub_t).doit(), eps).subs(eps, 0)


for (i, j, nm) in [(0, 0, 'rr'), (1, 1, 'thth')]:
    report(zero(ddt(g[i, j]) - adm_g[i, j]), f'd_t gamma_{nm} from BSSN == ADM')
    report(zero(ddt(Kdd[i, j]) - (adm_K[i, j] - fal*g[i, j]*Hdir/3)),
           f'd_t K_{nm} from BSSN == ADM - (alpha/3) gamma_{nm} H')
report(zero(Ricci_rr(fa, fb, fphi, Lg) - gi[0, 0]*Rdir[0, 0]), 'R^r_r (with Delta^r=Delta^r(a,b)) == direct Ricci of gamma_ij')
report(zero(Ricci_thth(fa, fb, fphi, Lg) - gi[1, 1]*Rdir[1, 1]), 'R^theta_theta (with Delta^r=Delta^r(a,b)) == direct Ricci')
report(zero(Ricci_rr(fa, fb, fphi, fL) - Ricci_rr(fa, fb, fphi, Lg) - sp.exp(-4*fphi)*D(gconstraint(fa, fb, fL)))
       and zero(Ricci_thth(fa, fb, fphi, fL) - Ricci_thth(fa, fb, fphi, Lg) - sp.exp(-4*fphi)*gconstraint(fa, fb, fL)/r),
       'R^r_r = R^r_r[metric] + e^{-4phi} d_r G^r,  R^th_th = R^th_th[metric] + e^{-4phi} G^r / r')
report(zero(Ricci_scalar_metric(fa, fb, fphi) - sum((gi*Rdir)[i, i] for i in range(3))), 'metric-only Ricci scalar formula')
report(zero(hamiltonian(fa, fb, fphi, fK, fAa, -fAa/2, Lg) - Hdir), 'Hamiltonian constraint == R + K^2 - K_ij K^ij')
# momentum constraint: D_j K^j_i - d_i K
Gm = G
Mr = (sum(pd(Kmix[j, 0], j) for j in range(3)) + sum(Gm[j][j][l]*Kmix[l, 0] for j in range(3) for l in range(3))
      - sum(Gm[l][j][0]*Kmix[j, l] for j in range(3) for l in range(3)) - pd(trK, 0))
report(zero(momentum(fa, fb, fphi, fK, fAa, -fAa/2) - Mr), 'momentum constraint M_r == D_j K^j_r - d_r K')
# d_t Delta^r vs chain rule
dtDg = ddt(Lg)
ratio = sp.simplify((o['L'] - dtDg)/momentum(fa, fb, fphi, fK, fAa, -fAa/2))
report(zero(ratio - 2*fal/fa), 'd_t Delta^r(evolved eq.) - d_t[Delta^r(a,b)] == (2 alpha / a) M_r   [ratio=%s]' % ratio)
# 1+log / Gamma driver sanity: B eq with advection uses d_t Delta^r
print(f'      ({time.time()-t:.1f}s)', flush=True)

# ============================================================================
print('=== V4: chi = e^{-4 phi} forms ===', flush=True)
chi_ = sp.exp(-4*fphi)
report(zero(rhs_chi(fa, fb, chi_, fK, fal, fbe) - (-4*chi_*o['phi'])), 'd_t chi')
report(zero(lap_alpha_chi(fa, fb, chi_, fal) - lap_alpha(fa, fb, fphi, fal)), 'D^2 alpha (chi form)')
report(zero(DrDr_minus_DthDth_chi(fa, fb, chi_, fal) - (DrDr_alpha(fa, fb, fphi, fal) - DthDth_alpha(fa, fb, fphi, fal))),
       'D^rD_r alpha - D^thD_th alpha (chi form)')
report(zero(DrDr_minus_DthDth_alpha(fa, fb, fphi, fal) - (DrDr_alpha(fa, fb, fphi, fal) - DthDth_alpha(fa, fb, fphi, fal))),
       'D^rD_r alpha - D^thD_th alpha (phi form, combined)')
report(zero(DrDr_alpha(fa, fb, fphi, fal) + 2*DthDth_alpha(fa, fb, fphi, fal) - lap_alpha(fa, fb, fphi, fal)),
       'D^2 alpha = D^rD_r alpha + 2 D^thD_th alpha')
report(zero(Ricci_scalar_metric_chi(fa, fb, chi_) - Ricci_scalar_metric(fa, fb, fphi)), 'metric-only R (chi form)')
report(zero(DrDr_alpha_chi(fa, fb, chi_, fal) - DrDr_alpha(fa, fb, fphi, fal)), 'D^rD_r alpha (chi form)')
report(zero(DthDth_alpha_chi(fa, fb, chi_, fal) - DthDth_alpha(fa, fb, fphi, fal)), 'D^thD_th alpha (chi form)')
report(zero(Ricci_rr_chi(fa, fb, chi_, fL) - Ricci_rr(fa, fb, fphi, fL)), 'R^r_r (chi form)')
report(zero(Ricci_thth_chi(fa, fb, chi_, fL) - Ricci_thth(fa, fb, fphi, fL)), 'R^theta_theta (chi form)')
report(zero(rhs_L_chi_piece(fa, fAa, fal, chi_) - (-2*fAa/fa*(D(fal) - 6*fal*D(fphi)))), 'Delta^r RHS chi-dependent term')
report(zero(momentum_chi(fa, fb, chi_, fK, fAa) - momentum(fa, fb, fphi, fK, fAa, -fAa/2)), 'momentum constraint (chi form)')
fa_p, fb_p, fpsi_p = [sp.Function(n, positive=True)(r) for n in ['a', 'b', 'psi']]
report(zero(expansion_chi(fa_p, fb_p, fpsi_p**-4, fK, fAa) - expansion(fa_p, fb_p, sp.log(fpsi_p), fK, fAa)),
       'expansion Theta (chi form)')
RA = areal_radius(fb_p, sp.log(fpsi_p))
report(zero(expansion(fa_p, fb_p, sp.log(fpsi_p), fK, fAa)
            - (2/RA*sp.exp(-2*sp.log(fpsi_p))/sp.sqrt(fa_p)*D(RA) - 2*(-fAa/2 + fK/3))),
       'Theta = (2/R_A) e^{-2phi} R_A\'/sqrt(a) - 2 K^theta_theta')
report(zero(misner_sharp(fa_p, fb_p, sp.log(fpsi_p), fK, -fAa/2).subs(fAa, sp.solve(
    expansion(fa_p, fb_p, sp.log(fpsi_p), fK, fAa), fAa)[0]) - RA/2),
       'Misner-Sharp mass = R_A/2 wherever Theta_+ = 0')

# ============================================================================


def stationary_test(name, a, b, phi, alpha, beta, r_h, Mexp, extra_subs=None, expect_K0=False):
    """Given stationary physical data (gamma from a,b,phi; alpha; beta^r), build K_ij from
    d_t gamma_ij = 0  =>  K_ij = Lie_beta gamma_ij / (2 alpha); then all BSSN field RHS must vanish."""
    g = sp.exp(4*phi)*sph_diag(a, b)
    Kdd = lie_cov2(g, [beta, 0, 0])/(2*alpha)
    gi = g.inv()
    Krr = sp.simplify(gi[0, 0]*Kdd[0, 0])
    Ktt = sp.simplify(gi[1, 1]*Kdd[1, 1])
    K = sp.simplify(Krr + 2*Ktt)
    Aa = sp.simplify(Krr - K/3)
    Ab = sp.simplify(Ktt - K/3)
    L = Delta_gamma(a, b)
    ok = zero(Ab + Aa/2) and zero(gi[2, 2]*Kdd[2, 2] - Ktt)
    report(ok, f'{name}: K_ij from stationarity; A_b = -A_a/2')
    if expect_K0:
        report(zero(K), f'{name}: slice is maximal (K=0)')
    o = rhs_1d(a, b, phi, K, Aa, Ab, L, alpha, beta)
    for k in ['phi', 'a', 'b', 'K', 'Aa', 'Ab', 'L']:
        report(zero(o[k]), f'{name}: d_t {k} = 0')
    report(zero(rhs_L_traceless(a, b, phi, K, Aa, L, alpha, beta)), f'{name}: d_t Delta^r = 0 (traceless form)')
    chi = sp.exp(-4*phi)
    report(zero(rhs_chi(a, b, chi, K, alpha, beta)), f'{name}: d_t chi = 0')
    report(zero(hamiltonian(a, b, phi, K, Aa, Ab, L)), f'{name}: Hamiltonian constraint = 0')
    report(zero(sp.exp(4*phi)*(Ricci_scalar_metric(a, b, phi) - Aa**2 - 2*Ab**2 + sp.Rational(2, 3)*K**2)),
           f'{name}: Hamiltonian constraint (metric-only R) = 0')
    report(zero(momentum(a, b, phi, K, Aa, Ab)), f'{name}: momentum constraint = 0')
    Th = expansion(a, b, phi, K, Aa)
    report(zero(Th.subs(r, r_h)), f'{name}: Theta(r={r_h}) = 0')
    report(zero(areal_radius(b, phi).subs(r, r_h)/2 - Mexp), f'{name}: M_AH = R_areal(r_AH)/2 = M')
    report(zero(misner_sharp(a, b, phi, K, Ab) - Mexp), f'{name}: Misner-Sharp mass = M everywhere')
    return K, Aa


print('=== V5: Schwarzschild, isotropic, static ===', flush=True)
t = time.time()
psi_s = 1 + M/(2*r)
phi_s = sp.log(psi_s)
al_s = (1 - M/(2*r))/(1 + M/(2*r))
K_s, Aa_s = stationary_test('Schw-isotropic', sp.Integer(1), sp.Integer(1), phi_s, al_s, sp.Integer(0),
                            M/2, M)
o = rhs_1d(sp.Integer(1), sp.Integer(1), phi_s, sp.Integer(0), sp.Integer(0), sp.Integer(0), sp.Integer(0), al_s, sp.Integer(0))
eta = sp.symbols('eta', positive=True)
gr = gauge_rhs(sp.Integer(0), al_s, sp.Integer(0), sp.Integer(0), sp.Integer(0), o['L'], eta)
report(zero(gr['alpha']) and zero(gr['beta']) and zero(gr['B']), 'Schw-isotropic: 1+log and Gamma-driver RHS vanish (K=0, beta=B=0)')
report(zero(gconstraint(sp.Integer(1), sp.Integer(1), sp.Integer(0))), 'Schw-isotropic: G^r = 0 with Delta^r = 0')
report(zero(K_s) and zero(Aa_s), 'Schw-isotropic: K = A_a = 0')
print(f'      ({time.time()-t:.1f}s)', flush=True)

print('=== V6: stationary data with non-zero shift ===', flush=True)
t = time.time()
H_ = 2*M/r
al_ks = 1/sp.sqrt(1 + H_)
be_ks = H_/(1 + H_)
Kks, Aks = stationary_test('Kerr-Schild (phi=0, a=1+2M/r, b=1)', 1 + H_, sp.Integer(1), sp.Integer(0), al_ks, be_ks, 2*M, M)
report(zero(Kks - 2*M*(r + 3*M)/(r**sp.Rational(3, 2)*(r + 2*M)**sp.Rational(3, 2)))
       and zero(Aks + 4*M*(2*r + 3*M)/(3*r**sp.Rational(3, 2)*(r + 2*M)**sp.Rational(3, 2)))
       and zero(Delta_gamma(1 + H_, sp.Integer(1)) - M*(3*r + 8*M)/(r*(r + 2*M)**2)),
       'Kerr-Schild explicit K, A_a, Delta^r as listed in the .md')
stationary_test('Kerr-Schild (det gbar = det ghat: a=(1+2M/r)^(2/3), b=(1+2M/r)^(-1/3))',
                (1 + H_)**sp.Rational(2, 3), (1 + H_)**sp.Rational(-1, 3), sp.log(1 + H_)/12, al_ks, be_ks, 2*M, M)
Kpg, Apg = stationary_test('Painleve-Gullstrand (a=b=1, phi=0, alpha=1, beta=sqrt(2M/r))', sp.Integer(1), sp.Integer(1),
                           sp.Integer(0), sp.Integer(1), sp.sqrt(2*M/r), 2*M, M)
report(zero(Kpg - sp.Rational(3, 2)*sp.sqrt(2*M)*r**sp.Rational(-3, 2)) and zero(Apg + sp.sqrt(2*M)*r**sp.Rational(-3, 2)),
       'Painleve-Gullstrand explicit K, A_a as listed in the .md')
C = sp.symbols('C', positive=True)
f_ = 1 - 2*M/r + C**2/r**4
Kmx, Amx = stationary_test('maximal slice, areal coords (a=1/f, b=1, alpha=sqrt f, beta=C sqrt(f)/r^2)',
                           1/f_, sp.Integer(1), sp.Integer(0), sp.sqrt(f_), C*sp.sqrt(f_)/r**2, 2*M, M, expect_K0=True)
report(zero(Amx + 2*C/r**3) and zero(Delta_gamma(1/f_, sp.Integer(1)) - 3*M/r**2),
       'maximal slice explicit A_a = -2C/r^3, Delta^r = 3M/r^2')
Ctr = 3*sp.sqrt(3)*M**2/4
# --- Baumgarte & Naculich (2007) maximal trumpet in ISOTROPIC coordinates.  The areal radius
#     R(r) is defined implicitly by dR/dr = R sqrt(f)/r (so that dR^2/f = psi^4 dr^2, psi^2 = R/r).
#     Fields are written in terms of r and R, and d/dr acts as  d_r + (R sqrt f / r) d_R.
Rs = sp.symbols('R', positive=True)
fR = 1 - 2*M/Rs + Ctr**2/Rs**4
sqf = (2*Rs - 3*M)*sp.sqrt(4*Rs**2 + 4*M*Rs + 3*M**2)/(4*Rs**2)   # = sqrt(f) for R > 3M/2
report(zero(sqf**2 - fR), 'BN trumpet: sqrt(f) = (2R-3M) sqrt(4R^2+4MR+3M^2)/(4R^2)')


def Dr_chain(e):
    return sp.diff(e, r) + sp.diff(e, Rs)*Rs*sqf/r


phi_g = sp.Function('phi')(r)
gen = rhs_1d(fa, fb, phi_g, fK, fAa, -fAa/2, fL, fal, fbe)
bn = {fa: sp.Integer(1), fb: sp.Integer(1), phi_g: sp.log(Rs/r)/2, fal: sqf, fbe: Ctr*r/Rs**3}
grr_bn = sp.exp(4*bn[phi_g])
Krr_mix = (bn[fbe]*Dr_chain(grr_bn) + 2*grr_bn*Dr_chain(bn[fbe]))/(2*bn[fal]*grr_bn)
Ktt_mix = bn[fbe]*Dr_chain(grr_bn*r**2)/(2*bn[fal]*grr_bn*r**2)
bn[fK] = sp.simplify(Krr_mix + 2*Ktt_mix)
bn[fAa] = sp.simplify(Krr_mix - bn[fK]/3)
bn[fL] = sp.Integer(0)                      # a=b=1  ->  Delta^r(a,b) = 0
report(zero(bn[fK]) and zero(bn[fAa] + 2*Ctr/Rs**3) and zero(Ktt_mix - Ctr/Rs**3),
       'BN trumpet (isotropic): K=0, A_a=-2C/R^3, K^th_th = C/R^3')


def bn_value(e):
    reps = {}
    for F, E in bn.items():
        reps[sp.Derivative(F, (r, 2))] = Dr_chain(Dr_chain(E))
        reps[sp.Derivative(F, r)] = Dr_chain(E)
    e = e.xreplace({k: v for k, v in reps.items() if k.derivative_count == 2})
    e = e.xreplace({k: v for k, v in reps.items() if k.derivative_count == 1})
    return e.xreplace(bn)


for k in ['phi', 'a', 'b', 'K', 'Aa', 'L']:
    report(zero(bn_value(gen[k])), f'BN maximal trumpet, isotropic coords, non-zero shift beta=C r/R^3: d_t {k} = 0')
report(zero(bn_value(hamiltonian(fa, fb, phi_g, fK, fAa, -fAa/2, fL))), 'BN trumpet: Hamiltonian constraint = 0')
report(zero(bn_value(momentum(fa, fb, phi_g, fK, fAa, -fAa/2))), 'BN trumpet: momentum constraint = 0')
report(zero(bn_value(misner_sharp(fa, fb, phi_g, fK, -fAa/2)) - M), 'BN trumpet: Misner-Sharp mass = M')
report(zero(bn_value(expansion(fa, fb, phi_g, fK, fAa)).subs(Rs, 2*M)), 'BN trumpet: Theta = 0 where R_areal = 2M')
# closed form r(R) of Baumgarte & Naculich (2007): check it solves dr/dR = r/(R sqrt f), numerically
r_bn = ((2*Rs + M + sp.sqrt(4*Rs**2 + 4*M*Rs + 3*M**2))/4
        * ((4 + 3*sp.sqrt(2))*(2*Rs - 3*M)/(8*Rs + 6*M + 3*sp.sqrt(8*Rs**2 + 8*M*Rs + 6*M**2)))**(1/sp.sqrt(2)))
ode_res = sp.diff(r_bn, Rs) - r_bn/(Rs*sqf)
vals = [abs(sp.N(ode_res.subs({M: 1, Rs: R0}), 40)) for R0 in [sp.Rational(8, 5), 2, 3, 7, 50]]
report(max(vals) < 1e-30, f'BN closed-form r(R) solves dr/dR = r/(R sqrt f) (max residual {float(max(vals)):.1e})')
report(abs(sp.N(sp.limit(r_bn/Rs, Rs, sp.oo).subs(M, 1)) - 1) < 1e-12, 'BN closed form: r/R -> 1 as R -> infinity')
report(zero(sp.diff(f_.subs(C, Ctr), r).subs(r, 3*M/2)) and zero(f_.subs(C, Ctr).subs(r, 3*M/2)),
       'trumpet value C = 3 sqrt(3) M^2/4: f and f\' vanish at R = 3M/2 (double root)')
print(f'      ({time.time()-t:.1f}s)', flush=True)

# ============================================================================
print('=== V7: parity and regularity at r = 0 ===', flush=True)
t = time.time()
# parity: even fields = E(r^2), odd fields = r*O(r^2)
Ea, Eb, Ep, EK, EA, Eal = [sp.Function(n)(r**2) for n in ['Ea', 'Eb', 'Ep', 'EK', 'EA', 'Eal']]
OL, Obe, OB = [r*sp.Function(n)(r**2) for n in ['OL', 'Obe', 'OB']]
o = rhs_1d(Ea, Eb, Ep, EK, EA, -EA/2, OL, Eal, Obe)
gr = gauge_rhs(EK, Eal, Obe, OB, OL, o['L'], eta)
rr = sp.symbols('rr', positive=True)


def parity_of(expr):
    e_p = expr.subs(r, rr)
    e_m = expr.subs(r, -rr)
    if zero(e_p - e_m):
        return +1
    if zero(e_p + e_m):
        return -1
    return 0


par_expect = {'phi': 1, 'a': 1, 'b': 1, 'K': 1, 'Aa': 1, 'Ab': 1, 'L': -1}
for k, pexp in par_expect.items():
    report(parity_of(o[k]) == pexp, f'parity of d_t {k} is {"even" if pexp > 0 else "odd"}')
for k, pexp in [('alpha', 1), ('beta', -1), ('B', -1)]:
    report(parity_of(gr[k]) == pexp, f'parity of d_t {k} is {"even" if pexp > 0 else "odd"}')
report(parity_of(divbeta(Ea, Eb, Obe)) == 1 and parity_of(hamiltonian(Ea, Eb, Ep, EK, EA, -EA/2, OL)) == 1
       and parity_of(Ricci_rr(Ea, Eb, Ep, OL)) == 1 and parity_of(Ricci_thth(Ea, Eb, Ep, OL)) == 1,
       'Dbar.beta, H, R^r_r, R^theta_theta are even')
report(parity_of(momentum(Ea, Eb, Ep, EK, EA, -EA/2)) == -1 and parity_of(gconstraint(Ea, Eb, OL)) == -1,
       'M_r and G^r are odd')
report(parity_of(expansion(Ea, Eb, Ep, EK, EA) - EA + 2*EK/3) == -1,
       'geometric part of Theta is odd (~2/r), extrinsic part even')
# regularity: truncated Taylor data with local flatness a(0)=b(0), A_a(0)=0.
# phi = log(psi) with psi even, so every RHS is a rational function of r and the
# order of a pole at r=0 can be read off exactly from numerator/denominator.
# Taylor coefficients: random rationals (a cancellation of a pole would have to be an
# identity in the coefficients, so random values expose any uncancelled 1/r term).
rng = random.Random(12345)


def rnd():
    return sp.Rational(rng.randint(1, 9), rng.randint(1, 9))


def regular_data():
    a0 = rnd()
    d_ = dict(ta=a0 + rnd()*r**2, tb=a0 + rnd()*r**2,
              tp=sp.log(rnd() + rnd()*r**2), tK=rnd() + rnd()*r**2,
              tA=rnd()*r**2, tL=rnd()*r + rnd()*r**3, tal=rnd() + rnd()*r**2,
              tbe=rnd()*r + rnd()*r**3, tB=rnd()*r + rnd()*r**3)
    return d_


def low_order(expr):
    """(order of the leading power of r at r=0, leading coefficient) for a rational function."""
    n, d_ = sp.fraction(sp.cancel(sp.together(sp.expand(expr))))
    pn, pdn = sp.Poly(sp.expand(n), r), sp.Poly(sp.expand(d_), r)
    if pn.is_zero:
        return sp.oo, 0
    on = min(m[0] for m in pn.monoms())
    od = min(m[0] for m in pdn.monoms())
    return on - od, sp.simplify(pn.coeff_monomial(r**on)/pdn.coeff_monomial(r**od))


okA = okB = okC = okD = okE = True
for trial in range(2):
    q = regular_data()
    ta, tb, tp, tK, tA, tL, tal, tbe, tB = [q[k] for k in ['ta', 'tb', 'tp', 'tK', 'tA', 'tL', 'tal', 'tbe', 'tB']]
    o = rhs_1d(ta, tb, tp, tK, tA, -tA/2, tL, tal, tbe)
    gr = gauge_rhs(tK, tal, tbe, tB, tL, o['L'], eta)
    orders = {k: low_order(o[k])[0] for k in ['phi', 'a', 'b', 'K', 'Aa', 'L']}
    orders.update({k: low_order(gr[k])[0] for k in ['alpha', 'beta', 'B']})
    if trial == 0:
        print('      leading power of r in each RHS at r=0 (trial 0):', orders)
    okA = okA and all(orders[k] >= 0 for k in ['phi', 'a', 'b', 'K', 'Aa', 'alpha'])
    okA = okA and all(orders[k] >= 1 for k in ['L', 'beta', 'B'])
    okB = okB and orders['Aa'] >= 2
    okC = okC and low_order(o['a'] - o['b'])[0] >= 2
    Hh = hamiltonian(ta, tb, tp, tK, tA, -tA/2, tL)
    Mm = momentum(ta, tb, tp, tK, tA, -tA/2)
    okD = okD and low_order(Hh)[0] >= 0 and low_order(Mm)[0] >= 1 and low_order(gconstraint(ta, tb, tL))[0] >= 1
    # each individual Ricci component is finite
    okE = okE and low_order(Ricci_rr(ta, tb, tp, tL))[0] >= 0 and low_order(Ricci_thth(ta, tb, tp, tL))[0] >= 0
    okF = (trial == 0 or okF) and zero(sp.limit(r*expansion(ta, tb, tp, tK, tA), r, 0)
                                       - 2*sp.exp(-2*tp.subs(r, 0))/sp.sqrt(ta.subs(r, 0)))
report(okA, 'all RHS finite at r=0 for regular data; odd RHS (Delta^r, beta, B) vanish at r=0')
report(okB, 'd_t A_a = O(r^2)  (A_a(0)=0, i.e. A_a=A_b at the origin, is preserved)')
report(okC, 'd_t (a-b) = O(r^2)  (local flatness a(0)=b(0) is preserved)')
report(okD, 'H finite, M_r = O(r), G^r = O(r) at r=0 for regular data')
report(okE, 'R^r_r and R^theta_theta individually finite at r=0')
report(okF, 'Theta_+ ~ 2 e^{-2phi}/(sqrt(a) r) as r -> 0')
print(f'      ({time.time()-t:.1f}s)', flush=True)

# ============================================================================
print('=== V8: Z4c with constraint damping (Sec. 17) ===', flush=True)
t = time.time()
fKh, fTh = [sp.Function(n)(r) for n in ['Khat', 'Theta']]
k1, k2 = sp.symbols('kappa1 kappa2')
Abar_z = sp.diag(fa*fAa, r**2*fb*(-fAa/2), r**2*fb*(-fAa/2)*sp.sin(th)**2)
Z3 = brown_z4c_rhs_3d(sph_diag(fa, fb), sph_diag(1, 1), Abar_z, fphi, fKh, fTh, [fL, 0, 0], fal,
                      [fbe, 0, 0], k1, k2)
z1 = rhs_z4c_1d(fa, fb, fphi, fKh, fTh, fAa, fL, fal, fbe, k1, k2)
report(zero(Z3['phi'] - z1['phi']), 'Z4c 3D == 1D: d_t phi (K = K-hat + 2 Theta)')
report(zero(Z3['gb'][0, 0] - z1['a']) and zero(Z3['gb'][1, 1]/r**2 - z1['b']), 'Z4c 3D == 1D: d_t a, d_t b')
report(zero(Z3['K'] - z1['K']), 'Z4c 3D == 1D: d_t K-hat')
report(zero((Z3['Abar'][0, 0] - fAa*Z3['gb'][0, 0])/fa - z1['Aa']), 'Z4c 3D == 1D: d_t A_a')
report(zero(Z3['L'][0] - z1['L']) and zero(Z3['L'][1]) and zero(Z3['L'][2]), 'Z4c 3D == 1D: d_t Delta^r (Lambda^theta = Lambda^phi = 0)')
report(zero(Z3['Theta'] - z1['Theta']), 'Z4c 3D == 1D: d_t Theta')
# Theta = 0 and Delta^r = Delta_gamma^r (no constraint violation of Z4's kind): Z4c is BSSN, and
# d_t Theta = (alpha/2) H, so that exact data (V5, V6: BSSN-stationary with H = 0) are Z4c-stationary
Lg = Delta_gamma(fa, fb)
zb = rhs_z4c_1d(fa, fb, fphi, fK, 0, fAa, Lg, fal, fbe, k1, k2)
ob = rhs_1d(fa, fb, fphi, fK, fAa, -fAa/2, Lg, fal, fbe)
report(all(zero(zb[k] - ob[k]) for k in ['phi', 'a', 'b', 'K', 'Aa', 'L']),
       'Theta = 0, G^r = 0: the Z4c RHS equal the BSSN RHS (every field, any kappa1, kappa2)')
report(zero(zb['Theta'] - fal/2*hamiltonian(fa, fb, fphi, fK, fAa, -fAa/2, Lg)),
       'Theta = 0, G^r = 0: d_t Theta = (alpha/2) H')
# Constraint subsystem, arbitrary data (Theta, G^r != 0): with K = K-hat + 2 Theta and
# G^r = Delta^r - Delta_gamma^r,
#  (I1) d_t(K-hat + 2 Theta) = [beta K' - D^2 alpha + alpha (R[metric] + K^2)] (ADM's d_t K before
#       the Hamiltonian constraint is used) + alpha e^{-4 phi}(d_r G^r + 2 G^r/r) - 3 alpha kappa1 (1 + kappa2) Theta
#  (I3) d_t Theta - beta Theta' + alpha kappa1 (2 + kappa2) Theta = (alpha/2)[H + e^{-4 phi}(d_r G^r + 2 G^r/r)]
#  (I2) at G^r = 0: d_t Delta^r - d_t[Delta_gamma^r(a, b)] = (2 alpha/a)(M_r + d_r Theta) (Z4's
#       d_t Z_r = alpha (M_r + d_r Theta) + ..., Delta^r - Delta_gamma^r = 2 gbar^rr Z_r), and
#       d(d_t Delta^r)/d kappa1 = -2 alpha G^r
K_ = fKh + 2*fTh
Gr = gconstraint(fa, fb, fL)
divG = sp.exp(-4*fphi)*(D(Gr) + 2*Gr/r)
adm_dtK = fbe*D(K_) - lap_alpha(fa, fb, fphi, fal) + fal*(Ricci_scalar_metric(fa, fb, fphi) + K_**2)
report(zero(z1['K'] + 2*z1['Theta'] - adm_dtK - fal*divG + 3*fal*k1*(1 + k2)*fTh),
       '(I1) d_t(K-hat + 2 Theta) = ADM d_t K + alpha e^{-4phi} div G - 3 alpha kappa1 (1 + kappa2) Theta')
report(zero(z1['Theta'] - fbe*D(fTh) + fal*k1*(2 + k2)*fTh
            - fal/2*(hamiltonian(fa, fb, fphi, K_, fAa, -fAa/2, Lg) + divG)),
       '(I3) d_t Theta = beta Theta\' + (alpha/2)(H + e^{-4phi} div G) - alpha kappa1 (2 + kappa2) Theta')
zg = rhs_z4c_1d(fa, fb, fphi, fKh, fTh, fAa, Lg, fal, fbe, k1, k2)
sub_z = {fa: fa + eps*zg['a'], fb: fb + eps*zg['b']}
dtDg_z = sp.diff(Lg.xreplace(sub_z).doit(), eps).subs(eps, 0)
report(zero(zg['L'] - dtDg_z - 2*fal/fa*(momentum(fa, fb, fphi, K_, fAa, -fAa/2) + D(fTh))),
       '(I2) G^r = 0: d_t Delta^r - d_t Delta_gamma^r = (2 alpha/a)(M_r + d_r Theta)')
report(zero(sp.diff(z1['L'], k1) + 2*fal*Gr), '(I2) the damping of Delta^r: d/dkappa1 d_t Delta^r = -2 alpha G^r')
print(f'      ({time.time()-t:.1f}s)', flush=True)

# ============================================================================
print('=== V9: Eulerian volume choice, sigma = 0 (Sec. 18) ===', flush=True)
t = time.time()
# V1e: the 3D covariant RHS with sigma = 0 against the 1D Eulerian formulas, as V1 does for
# sigma = 1.  The 3D RHS is built once with a symbol sigma (it is affine in sigma) and set to 0.
sg = sp.symbols('sigma')
gb = sph_diag(fa, fb)
gh = sph_diag(1, 1)
for label, Ab_ in [('A_b general', fAb), ('A_b=-A_a/2', -fAa/2)]:
    Abar = sp.diag(fa*fAa, r**2*fb*Ab_, r**2*fb*Ab_*sp.sin(th)**2)
    R3s = brown_bssn_rhs_3d(gb, gh, Abar, fphi, fK, [fL, 0, 0], fal, [fbe, 0, 0], sigma=sg)
    R3e = {'gb': R3s['gb'].subs(sg, 0), 'Abar': R3s['Abar'].subs(sg, 0), 'phi': R3s['phi'].subs(sg, 0),
           'K': R3s['K'].subs(sg, 0), 'L': [x.subs(sg, 0) for x in R3s['L']]}
    oe = rhs_1d_eulerian(fa, fb, fphi, fK, fAa, Ab_, fL, fal, fbe)
    ok = all(zero(R3e['gb'][i, j]) and zero(R3e['Abar'][i, j]) for i in range(3) for j in range(3) if i != j)
    ok = ok and zero(R3e['gb'][2, 2] - sp.sin(th)**2*R3e['gb'][1, 1]) and zero(R3e['Abar'][2, 2] - sp.sin(th)**2*R3e['Abar'][1, 1])
    ok = ok and zero(R3e['L'][1]) and zero(R3e['L'][2])
    report(ok, f'V1e [{label}] 3D RHS (sigma=0) is diagonal, spherically symmetric, Lambda^theta=Lambda^phi=0')
    rhs_a3 = R3e['gb'][0, 0]
    rhs_b3 = R3e['gb'][1, 1]/r**2
    rhs_Aa3 = (R3e['Abar'][0, 0] - fAa*rhs_a3)/fa
    rhs_Ab3 = (R3e['Abar'][1, 1]/r**2 - Ab_*rhs_b3)/fb
    report(zero(R3e['phi'] - oe['phi']), f'V1e [{label}] d_t phi  (E1e)')
    report(zero(rhs_a3 - oe['a']), f'V1e [{label}] d_t a  (E2e)')
    report(zero(rhs_b3 - oe['b']), f'V1e [{label}] d_t b  (E3e)')
    report(zero(R3e['K'] - oe['K']), f'V1e [{label}] d_t K  (E4e = E4)')
    report(zero(rhs_Aa3 - oe['Aa']), f'V1e [{label}] d_t A_a  (E5e = E5)')
    report(zero(rhs_Ab3 - oe['Ab']), f'V1e [{label}] d_t A_b  (= E5b)')
    report(zero(R3e['L'][0] - oe['L']), f'V1e [{label}] d_t Delta^r  (E6e)')
    if Ab_ is not fAb:
        report(zero(R3e['L'][0] - rhs_L_eulerian(fa, fb, fphi, fK, fAa, fL, fal, fbe)),
               f'V1e [{label}] d_t Delta^r, traceless-substituted form (E6e)')
        report(zero(rhs_Ab3 + rhs_Aa3/2), f'V1e [{label}] d_t A_b = -d_t A_a/2 (trace preserved)')
    else:
        # sigma's terms from the definitions (any sigma, 3D): the physical gamma_ij = e^{4 phi} gbar_ij
        # and A_ij = e^{4 phi} Abar_ij do not see sigma; Lambda^r's sigma terms are the change of
        # Delta^r(a, b) that the sigma part of d_t gbar_ij causes; d_t ln det gbar = 2 (1 - sigma) Dbar.beta
        # - 2 alpha Abar^k_k.
        dsg = {k: sp.diff(R3s[k], sg) for k in ['gb', 'Abar', 'phi']}
        e4p = sp.exp(4*fphi)
        ok = all(zero(e4p*(4*dsg['phi']*gb[i, i] + dsg['gb'][i, i])) for i in range(2))
        report(ok, 'sigma from the definitions: d/dsigma d_t(e^{4phi} gbar_ij) = 0 (rr, thth): the phi equation\'s sigma/6')
        ok = all(zero(e4p*(4*dsg['phi']*Abar[i, i] + dsg['Abar'][i, i])) for i in range(2))
        report(ok, 'sigma from the definitions: d/dsigma d_t(e^{4phi} Abar_ij) = 0 (rr, thth): Abar\'s -(2/3) sigma Abar Dbar.beta')
        sub_s = {fa: fa + eps*dsg['gb'][0, 0], fb: fb + eps*dsg['gb'][1, 1]/r**2}
        dDg = sp.diff(Delta_gamma(fa, fb).xreplace(sub_s).doit(), eps).subs(eps, 0)
        report(zero(sp.diff(R3s['L'][0], sg) - dDg),
               'sigma from the definitions: d/dsigma d_t Lambda^r = change of Delta^r(a, b) under gbar\'s sigma rescaling')
        gbi_ = gb.inv()
        trdot = sum(gbi_[i, j]*R3s['gb'][i, j] for i in range(3) for j in range(3))
        trA = sum(gbi_[i, j]*Abar[i, j] for i in range(3) for j in range(3))
        report(zero(trdot - 2*(1 - sg)*divbeta(fa, fb, fbe) + 2*fal*trA),
               'd_t ln det gbar = 2 (1 - sigma) Dbar.beta - 2 alpha Abar^k_k  (sigma=1: frozen, sigma=0: follows the shift)')
    print(f'      ({time.time()-t:.1f}s)', flush=True)

# Lagrangian minus Eulerian, equation by equation: exactly the sigma terms (sigma = 1)
dvb = divbeta(fa, fb, fbe)
oL = rhs_1d(fa, fb, fphi, fK, fAa, fAb, fL, fal, fbe)
oE = rhs_1d_eulerian(fa, fb, fphi, fK, fAa, fAb, fL, fal, fbe)
sigma_terms = {'phi': dvb/6, 'a': -sp.Rational(2, 3)*fa*dvb, 'b': -sp.Rational(2, 3)*fb*dvb,
               'K': 0, 'Aa': 0, 'Ab': 0,
               'L': sp.Rational(2, 3)*Delta_gamma(fa, fb)*dvb + divbeta_prime(fa, fb, fbe)/(3*fa)}
for k, v in sigma_terms.items():
    report(zero(oL[k] - oE[k] - v), f'Lagrangian - Eulerian, d_t {k}: {v if v == 0 else "the sigma term"}')
report(zero(rhs_L_traceless(fa, fb, fphi, fK, fAa, fL, fal, fbe) - rhs_L_eulerian(fa, fb, fphi, fK, fAa, fL, fal, fbe)
            - sigma_terms['L']),
       'Lagrangian - Eulerian, d_t Delta^r traceless form: (2/3) Delta_gamma^r Dbeta + (Dbeta)\'/(3a)')
chi_ = sp.exp(-4*fphi)
report(zero(rhs_chi(fa, fb, chi_, fK, fal, fbe) - rhs_chi_eulerian(fa, fb, chi_, fK, fal, fbe)
            + sp.Rational(2, 3)*chi_*dvb),
       'Lagrangian - Eulerian, d_t chi: -(2/3) chi Dbeta')
report(zero(rhs_chi_eulerian(fa, fb, chi_, fK, fal, fbe) - (-4*chi_*oE['phi'])), 'd_t chi (E1e, chi form) = -4 chi d_t phi')
report(zero(oE['a']/fa + 2*oE['b']/fb - 2*dvb + 2*fal*(fAa + 2*fAb)),
       'Eulerian: d_t ln(a b^2) = 2 Dbar.beta - 2 alpha (A_a + 2 A_b)  (= 2 Dbar.beta when trace-free)')
# ADM consistency (as V3) for the Eulerian system: the physical gamma_ij, K_ij evolve as in ADM
Lg = Delta_gamma(fa, fb)
oe = rhs_1d_eulerian(fa, fb, fphi, fK, fAa, -fAa/2, Lg, fal, fbe)
sub_te = {fa: fa + eps*oe['a'], fb: fb + eps*oe['b'], fpsi: fpsi*sp.exp(eps*oe['phi']),
          fK: fK + eps*oe['K'], fAa: fAa + eps*oe['Aa']}


def ddt_e(expr):
    return sp.diff(expr.xreplace(sub_te).doit(), eps).subs(eps, 0)


for (i, j, nm) in [(0, 0, 'rr'), (1, 1, 'thth')]:
    report(zero(ddt_e(g[i, j]) - adm_g[i, j]), f'Eulerian: d_t gamma_{nm} == ADM')
    report(zero(ddt_e(Kdd[i, j]) - (adm_K[i, j] - fal*g[i, j]*Hdir/3)),
           f'Eulerian: d_t K_{nm} == ADM - (alpha/3) gamma_{nm} H')
report(zero(oe['L'] - ddt_e(Lg) - 2*fal/fa*momentum(fa, fb, fphi, fK, fAa, -fAa/2)),
       'Eulerian: (E6e) - d_t[Delta^r(a,b)] (with E2e, E3e) == (2 alpha / a) M_r')
# Exact stationary data of V6 (non-zero shift): gamma_ij and K_ij stay stationary under either
# choice (d_t gamma_ij = d_t K_ij = 0 follows from V9's ADM check), but the Eulerian conformal
# variables do so only where Dbar.beta = 0 (Lagrangian - Eulerian is proportional to Dbar.beta and
# its derivative; d_t ln(a b^2) = 2 Dbar.beta).  For stationary data Dbar.beta = alpha K - 6 beta phi'.
def eulerian_on_stationary(name, value, expect_stationary):
    """value(expr) evaluates an expression in the generic functions on the data set."""
    oe_s = rhs_1d_eulerian(fa, fb, fphi, fK, fAa, -fAa/2, Lg, fal, fbe)
    phys = [sp.exp(4*fphi)*(4*oe_s['phi']*fa + oe_s['a']), sp.exp(4*fphi)*(4*oe_s['phi']*fb + oe_s['b']),
            oe_s['K'], oe_s['Aa']]
    ok = all(zero(value(x)) for x in phys)
    ok = ok and zero(value(oe_s['a']/fa + 2*oe_s['b']/fb - 2*divbeta(fa, fb, fbe)))
    if expect_stationary:
        ok = ok and all(zero(value(oe_s[k])) for k in ['phi', 'a', 'b', 'L'])
        what = 'Dbeta = 0: every Eulerian RHS vanishes'
    else:
        # one point of the data (M = 1; for the BN trumpet R = 3 and r = r(R) of the closed form)
        pt = {M: 1, Rs: 3, r: sp.N(r_bn.subs({M: 1, Rs: 3}), 40)}
        vals = [abs(sp.N(value(x).subs(pt), 30)) for x in [divbeta(fa, fb, fbe), oe_s['a']]]
        ok = ok and min(vals) > 1e-6
        what = 'but Dbeta != 0 and d_t a != 0'
    report(ok, f'Eulerian, {name}: d_t gamma_rr = d_t gamma_thth = d_t K = d_t A_a = 0, {what}')


def data_value(dat):
    def value(e):
        return e.subs(dat).doit()
    return value


def data_from_stationarity(a, b, phi, alpha, beta):
    g_ = sp.exp(4*phi)*sph_diag(a, b)
    Kdd_ = lie_cov2(g_, [beta, 0, 0])/(2*alpha)
    gi_ = g_.inv()
    Krr, Ktt = sp.simplify(gi_[0, 0]*Kdd_[0, 0]), sp.simplify(gi_[1, 1]*Kdd_[1, 1])
    return {fa: a, fb: b, fpsi: sp.exp(phi), fK: sp.simplify(Krr + 2*Ktt), fAa: sp.simplify(2*(Krr - Ktt)/3),
            fal: alpha, fbe: beta}


eulerian_on_stationary('Kerr-Schild (phi=0)', data_value(data_from_stationarity(
    1 + H_, sp.Integer(1), sp.Integer(0), al_ks, be_ks)), False)
eulerian_on_stationary('Kerr-Schild (a b^2 = 1)', data_value(data_from_stationarity(
    (1 + H_)**sp.Rational(2, 3), (1 + H_)**sp.Rational(-1, 3), sp.log(1 + H_)/12, al_ks, be_ks)), False)
eulerian_on_stationary('Painleve-Gullstrand', data_value(data_from_stationarity(
    sp.Integer(1), sp.Integer(1), sp.Integer(0), sp.Integer(1), sp.sqrt(2*M/r))), False)
eulerian_on_stationary('maximal slice, areal coords (any C)', data_value(data_from_stationarity(
    1/f_, sp.Integer(1), sp.Integer(0), sp.sqrt(f_), C*sp.sqrt(f_)/r**2)), True)
bn_e = {F: E for F, E in bn.items() if F is not phi_g}
bn_e[fpsi] = sp.sqrt(Rs/r)                   # phi = (1/2) ln(R/r)


def bn_value_e(e):
    """as bn_value, for expressions in psi (phi = ln psi) instead of phi(r)."""
    reps = {}
    for F, E in bn_e.items():
        reps[sp.Derivative(F, (r, 2))] = Dr_chain(Dr_chain(E))
        reps[sp.Derivative(F, r)] = Dr_chain(E)
    e = e.xreplace({k: v for k, v in reps.items() if k.derivative_count == 2})
    e = e.xreplace({k: v for k, v in reps.items() if k.derivative_count == 1})
    return e.xreplace(bn_e)


eulerian_on_stationary('BN maximal trumpet (isotropic)', bn_value_e, False)


# parity and regularity (as V7)
o = rhs_1d_eulerian(Ea, Eb, Ep, EK, EA, -EA/2, OL, Eal, Obe)
gr = gauge_rhs(EK, Eal, Obe, OB, OL, o['L'], eta)
ok = all(parity_of(o[k]) == p_ for k, p_ in par_expect.items()) and parity_of(gr['B']) == -1
report(ok, 'Eulerian: every RHS has the parity of its variable (phi, a, b, K, A_a, A_b even; Delta^r, B odd)')
okA = okB = okC = True
for trial in range(2):
    q = regular_data()
    ta, tb, tp, tK, tA, tL, tal, tbe, tB = [q[k] for k in ['ta', 'tb', 'tp', 'tK', 'tA', 'tL', 'tal', 'tbe', 'tB']]
    o = rhs_1d_eulerian(ta, tb, tp, tK, tA, -tA/2, tL, tal, tbe)
    gr = gauge_rhs(tK, tal, tbe, tB, tL, o['L'], eta)
    orders = {k: low_order(o[k])[0] for k in ['phi', 'a', 'b', 'K', 'Aa', 'L']}
    orders['B'] = low_order(gr['B'])[0]
    okA = okA and all(orders[k] >= 0 for k in ['phi', 'a', 'b', 'K', 'Aa']) and orders['L'] >= 1 and orders['B'] >= 1
    okB = okB and orders['Aa'] >= 2
    okC = okC and low_order(o['a'] - o['b'])[0] >= 2
report(okA, 'Eulerian: all RHS finite at r=0 for regular data; d_t Delta^r and d_t B vanish at r=0')
report(okB and okC, 'Eulerian: d_t A_a = O(r^2) and d_t (a-b) = O(r^2) at r=0')
print(f'      ({time.time()-t:.1f}s)', flush=True)

# ============================================================================
print('=== V10: massless scalar field (Sec. 19) ===', flush=True)
t = time.time()


fPhi, fPi = [sp.Function(n)(r) for n in ['Phi', 'Pi']]
chi10 = fpsi**-4                                  # chi = e^{-4 phi}, phi = log psi
g10 = sp.exp(4*fphi)*sph_diag(fa, fb)             # the physical metric
# the 4-metric at one instant, coordinates (t, r, theta, varphi); beta_r = gamma_rr beta
g4 = sp.zeros(4, 4)
g4[0, 0] = -fal**2 + g10[0, 0]*fbe**2
g4[0, 1] = g4[1, 0] = g10[0, 0]*fbe
for i in range(3):
    g4[i + 1, i + 1] = g10[i, i]
g4i = sp.simplify(g4.inv())
dPhi4 = [fbe*D(fPhi) + fal*fPi, D(fPhi), 0, 0]    # d_t Phi = beta Phi' + alpha Pi, (S1)
n_d = [-fal, 0, 0, 0]
n_u = [sp.simplify(sum(g4i[m, k]*n_d[k] for k in range(4))) for m in range(4)]
dPhi2 = sp.simplify(sum(g4i[m, k]*dPhi4[m]*dPhi4[k] for m in range(4) for k in range(4)))
T4 = sp.Matrix(4, 4, lambda m, k: dPhi4[m]*dPhi4[k] - g4[m, k]*dPhi2/2)
src = scalar_sources(fa, chi10, fPhi, fPi)
rho4 = sum(n_u[m]*n_u[k]*T4[m, k] for m in range(4) for k in range(4))
jr4 = -sum(n_u[k]*T4[1, k] for k in range(4))      # -gamma_r^a n^b T_ab, gamma_r^a = delta_r^a
report(zero(n_u[0] - 1/fal) and zero(n_u[1] + fbe/fal), 'n^a = (1, -beta)/alpha from the 4-metric')
report(zero(sum(n_u[m]*dPhi4[m] for m in range(4)) - fPi), 'Pi = n^a d_a Phi')
report(zero(rho4 - src['rho']), 'rho = n^a n^b T_ab')
report(zero(jr4 - src['jr']), 'j_r = -gamma_r^a n^b T_ab')
report(zero(T4[1, 1]/g10[0, 0] - src['Sa']) and zero(T4[2, 2]/g10[1, 1] - src['Sb']),
       'S^r_r and S^theta_theta = gamma^ii T_ii')
report(zero(src['Sa'] + 2*src['Sb'] - src['S']), 'S = S^r_r + 2 S^theta_theta')
# The Klein-Gordon equation: sqrt(-g) box Phi = d_mu (sqrt(-g) g^{mu nu} d_nu Phi) = 0 with the
# time derivatives of (S1)-(S2) and of the BSSN metric right-hand sides; the lapse's and the
# shift's rates are arbitrary (the gauge may not enter)
sqrtg4 = fal*sp.sqrt(g10[0, 0]*g10[1, 1]*g10[2, 2])
report(zero(sp.simplify(-g4.det()) - sqrtg4**2), 'sqrt(-g) = alpha sqrt(gamma)')
W = [sp.simplify(sqrtg4*sum(g4i[m, k]*dPhi4[k] for k in range(4))) for m in range(2)]
o10 = rhs_1d(fa, fb, fphi, fK, fAa, -fAa/2, Delta_gamma(fa, fb), fal, fbe)
sr = scalar_rhs(fa, fb, chi10, fK, fal, fbe, fPhi, fPi)
al_t, be_t = [sp.Function(n)(r) for n in ['alpha_t', 'beta_t']]
sub10 = {fa: fa + eps*o10['a'], fb: fb + eps*o10['b'], fpsi: fpsi*sp.exp(eps*o10['phi']),
         fPhi: fPhi + eps*sr['Phi'], fPi: fPi + eps*sr['Pi'], fal: fal + eps*al_t,
         fbe: fbe + eps*be_t, fK: fK + eps*o10['K'], fAa: fAa + eps*o10['Aa']}


def ddt10(expr):
    return sp.diff(expr.xreplace(sub10).doit(), eps).subs(eps, 0)


box = ddt10(W[0]) + D(W[1])
report(zero(sp.simplify(box/sp.sin(th))), 'box Phi = 0: (S1)-(S2) are the Klein-Gordon equation, any lapse and shift')
# The stress-energy of any matter in the ADM equations, d_t K_ij += -8 pi alpha (S_ij - (1/2)
# gamma_ij (S - rho)), H = 16 pi rho, D_j K^j_r - d_r K = 8 pi j_r: (S4)'s terms in d_t K and
# d_t A_a give it, with (E4)'s use of H = 16 pi rho (V3: d_t K_ij(BSSN) = d_t K_ij(ADM) -
# (alpha/3) gamma_ij (H - 16 pi rho)); and d_t Delta^r's term keeps (E6) - d_t Delta^r(a,b) =
# (2 alpha/a)(M_r - 8 pi j_r)
frho, fjr, fSa, fSb = [sp.Function(n)(r) for n in ['rho', 'j_r', 'S_a', 'S_b']]
gsrc = {'rho': frho, 'jr': fjr, 'Sa': fSa, 'Sb': fSb, 'S': fSa + 2*fSb}
mt = matter_terms(fa, fal, gsrc)
Sdd = sp.diag(g10[0, 0]*fSa, g10[1, 1]*fSb, g10[2, 2]*fSb)
adm_K_m = adm_K + -8*sp.pi*fal*(Sdd - g10*(gsrc['S'] - frho)/2)
o = rhs_1d(fa, fb, fphi, fK, fAa, -fAa/2, Lg, fal, fbe)   # V3's data again
sub_t_m = {fa: fa + eps*o['a'], fb: fb + eps*o['b'], fpsi: fpsi*sp.exp(eps*o['phi']),
           fK: fK + eps*(o['K'] + mt['K']), fAa: fAa + eps*(o['Aa'] + mt['Aa'])}


def ddt_m(expr):
    return sp.diff(expr.xreplace(sub_t_m).doit(), eps).subs(eps, 0)


for (i, j, nm) in [(0, 0, 'rr'), (1, 1, 'thth')]:
    report(zero(ddt_m(Kdd[i, j]) - (adm_K_m[i, j] - fal*g10[i, j]*(Hdir + mt['H'])/3)),
           f'with matter: d_t K_{nm} from BSSN (S4) == ADM - (alpha/3) gamma_{nm} (H - 16 pi rho)')
    report(zero(ddt_m(g[i, j]) - adm_g[i, j]), f'with matter: d_t gamma_{nm} unchanged')
Mr1 = momentum(fa, fb, fphi, fK, fAa, -fAa/2)
report(zero(o['L'] + mt['L'] - ddt(Lg) - 2*fal/fa*(Mr1 + mt['M'])),
       'with matter: d_t Delta^r - d_t[Delta^r(a,b)] == (2 alpha/a)(M_r - 8 pi j_r)')
# Z4c (Sec. 17) with the same terms: with Theta = 0 and Delta^r = Delta^r(a,b) it is BSSN with
# matter, and d_t Theta = (alpha/2)(H - 16 pi rho)
k1s, k2s = sp.symbols('kappa_1 kappa_2')
oz = rhs_z4c_1d(fa, fb, fphi, fK, 0, fAa, Lg, fal, fbe, k1s, k2s)
report(zero(oz['K'] + mt['K'] - (o['K'] + mt['K'])) and zero(oz['L'] + mt['L'] - (o['L'] + mt['L'])),
       'Z4c with matter, Theta = 0, G^r = 0: K-hat and Delta^r rates are BSSN\'s with matter')
report(zero(oz['Theta'] + mt['Theta'] - fal/2*(Hdir + mt['H'])), 'Z4c with matter: d_t Theta = (alpha/2)(H - 16 pi rho) at Theta = 0')
# parity: Phi and Pi even, their rates even; rho, S even, j_r odd (V7's even and odd functions)
EPhi, EPi = [sp.Function(n)(r**2) for n in ['EPhi', 'EPi']]
sr7 = scalar_rhs(Ea, Eb, sp.exp(-4*Ep), EK, Eal, Obe, EPhi, EPi)
src7 = scalar_sources(Ea, sp.exp(-4*Ep), EPhi, EPi)
report(parity_of(sr7['Phi']) == 1 and parity_of(sr7['Pi']) == 1, 'parity of d_t Phi and d_t Pi is even')
report(all(parity_of(src7[k]) == 1 for k in ['rho', 'Sa', 'Sb', 'S']) and parity_of(src7['jr']) == -1,
       'rho, S^r_r, S^theta_theta, S even; j_r odd')
print(f'      ({time.time()-t:.1f}s)', flush=True)

# ============================================================================
print('=== V11: energy flux through a sphere of fixed areal radius (S7) ===', flush=True)
t = time.time()
# (S7) as the equations document writes it, for any matter (the sources of V10, free functions)
R11 = areal_radius(fb, fphi)
e11 = sp.exp(-2*fphi)/sp.sqrt(fa)                  # (chi/a)^(1/2) = 1/sqrt(gamma_rr)
Gam11 = e11*D(R11)
U11 = -R11*(fK/3 - fAa/2)                           # -R K^theta_theta


def flux_S7(rho, jr, Srr):
    return 4*sp.pi*R11**2*fal/Gam11*(Gam11*U11*(rho + Srr) + (Gam11**2 + U11**2)*e11*jr)


m11 = misner_sharp(fa, fb, fphi, fK, -fAa/2)
report(zero(1 - 2*m11/R11 - (Gam11**2 - U11**2)), '1 - 2m/R = Gamma^2 - U^2 (T4)')
# d m/dt along the sphere R = const (the worldline dr/dt = -d_t R / R'), with the rates of BSSN
# with matter (V10's ddt_m); it is -F once the constraints with their sources hold, which here
# give rho and j_r: H - 16 pi rho = 0, M_r - 8 pi j_r = 0. S^r_r and S^theta_theta stay free.
dm_R = ddt_m(m11) - ddt_m(R11)/D(R11)*D(m11)
H11 = hamiltonian(fa, fb, fphi, fK, fAa, -fAa/2, Lg)
M11 = momentum(fa, fb, fphi, fK, fAa, -fAa/2)
on_shell = {frho: H11/(16*sp.pi), fjr: M11/(8*sp.pi)}
report(zero((dm_R + flux_S7(frho, fjr, fSa)).subs(on_shell)),
       'd m/dt at fixed R = -F of (S7), any lapse, shift and matter, on the constraints')
report(not zero((dm_R + flux_S7(frho, -fjr, fSa)).subs(on_shell)),
       'the same with j_r of the other sign fails (the check can fail)')
# the scalar field's: F = 4 pi R^2 (alpha/Gamma) (Gamma Pi - U Phi_e)(U Pi - Gamma Phi_e), with
# Phi_e = (chi/a)^(1/2) Phi' (T_ab's g_ab term drops out along the sphere)
src11 = scalar_sources(fa, fpsi**-4, fPhi, fPi)
Phi_e = e11*D(fPhi)
report(zero(flux_S7(src11['rho'], src11['jr'], src11['Sa'])
            - 4*sp.pi*R11**2*fal/Gam11*(Gam11*fPi - U11*Phi_e)*(U11*fPi - Gam11*Phi_e)),
       'scalar field: (S7) = 4 pi R^2 (alpha/Gamma)(Gamma Pi - U Phi_e)(U Pi - Gamma Phi_e)')
print(f'      ({time.time()-t:.1f}s)', flush=True)

print(f'\nTotal time {time.time()-T0:.1f}s;  failures: {NFAIL}')
sys.exit(1 if NFAIL else 0)
