#!/usr/bin/env python3
"""Hyperbolicity of the spherically symmetric GBSSN system with 1+log slicing, the Gamma-driver
shift and the horizon-adjusting shift, at the level of the continuum equations and of gbssn1d's
semi-discrete scheme (docs/horizon-shift-study.md, Sec. 10).

1. Continuum: the principal symbol P of the system linearised about frozen values of the fields
   (pseudo-differential reduction: the fields that appear with second derivatives, chi, a, b,
   alpha and beta_GD, are scaled by i k). Its eigenvalues are the characteristic speeds (up to
   sign); the system is strongly hyperbolic where they are real and P has a complete set of
   eigenvectors (a bounded condition number of the eigenvector matrix).
   beta_H = F(r) s^r enters through the full shift beta = beta_GD + beta_H; s^r depends on the
   metric (conformal normal 1/sqrt(a), unit normal sqrt(chi/a)), F = f(r) A (h_AH - h) x taper
   is a given function of r (h_AH is one number per time: its dependence on the state is not a
   differential operator and does not enter P).
2. Semi-discrete: the same linearisation with gbssn1d's 4th-order stencils in place of i k: the
   centred first and second derivatives, the lopsided (upwind) advection stencils chosen by the
   sign of the shift, each of the two stencil choices of beta d_r Delta^r (in d_t Delta^r and in
   B's driver), and Kreiss-Oliger dissipation. Frozen-coefficient von Neumann analysis: the
   eigenvalues of the symbol at every grid wave number theta = k dr in (0, pi] are h^-1 times
   numbers independent of the spacing h, so a positive real part is a growth rate proportional
   to the wave number (1/h), and the onset time of a blow-up proportional to the spacing.

Run:  python3 docs/hyperbolicity.py --check               self-checks and the predictions (~1 min)
      python3 docs/hyperbolicity.py --profiles DIR/profiles.dat [--driver-advection S ...]
                                                         growth rate and speeds on a run's fields
Needs Debian's python3-sympy and python3-numpy.
"""
import argparse
import sys

import numpy as np
import sympy as sp

r, k, eps = sp.symbols('r k epsilon', real=True)
SECOND = ['chi', 'a', 'b', 'alpha', 'beta']  # appear with second derivatives (scaled by i k)
FIRST = ['K', 'Aa', 'L', 'B']                # L = Delta^r
ORDER = SECOND + FIRST
F = sp.Function('F')(r)  # beta_H = F s^r
# Tags of the first-derivative terms that gbssn1d differences with an advection stencil:
#   adv: beta d_r f of every advected field (lopsided by the sign of the full shift),
#   dlt: beta d_r Delta^r of d_t Delta^r (--delta-advection),
#   drv: beta_GD d_r Delta^r of B's driver d_t Delta^r|_{beta_GD} (--driver-advection).
T_ADV, T_DLT, T_DRV = sp.symbols('T_adv T_dlt T_drv')
TAGS = (T_ADV, T_DLT, T_DRV)


def D(f, n=1):
    return sp.diff(f, r, n)


def rhs(u, normal, lapse_advective, driver_advective, split):
    """(C1), (E2)-(E6), (G1)-(G3) with (H1)-(H3), written from docs/gbssn1d-equations.md."""
    chi, a, b, al, bGD, K, Aa, L, Bv = (u[n] for n in ORDER)
    s = {'conformal': 1 / sp.sqrt(a), 'unit': sp.sqrt(chi / a), 'none': 0}[normal]
    beta = bGD + F * s  # (H1), (H3)

    def divb(be):  # (A1)
        return D(be) + be * (D(a) / (2 * a) + D(b) / b + 2 / r)

    def rhs_L(be, tag):  # (E6) with the shift be; tag marks its own advection term
        dvb = divb(be)
        dgam = (D(a) / (2 * a) - D(b) / b + 2 * (a / b - 1) / r) / a
        return (tag * be * D(L) - L * D(be) + D(be, 2) / a + 2 * D(be / r) / b
                + sp.Rational(2, 3) * dgam * dvb + D(dvb) / (3 * a)
                - 2 * Aa / a * (D(al) + sp.Rational(3, 2) * al * D(chi) / chi)
                + al * Aa / a * (D(a) / a + D(b) / b + 2 * (1 - a / b) / r)
                - sp.Rational(4, 3) * al * D(K) / a)

    def adv(f):
        return T_ADV * beta * D(f)

    dvb = divb(beta)
    lap = chi / a * (D(al, 2) - D(al) * (D(a) / (2 * a) - D(b) / b - 2 / r) - D(al) * D(chi) / (2 * chi))
    hess_tf = chi / a * (D(al, 2) - D(al) * (D(a) / (2 * a) + D(b) / (2 * b) + 1 / r) + D(al) * D(chi) / chi)
    bar_rr = (-D(a, 2) / (2 * a) + (D(a) / a)**2 - D(a) * D(b) / (2 * a * b) - (D(b) / b)**2 / 2
              - D(a) / (r * a) + 2 * D(b) / (r * b) * (a / b - 1) + 2 * (a / b - 1) / r**2) / a
    Rrr = chi * (D(L) + bar_rr + (D(chi, 2) / chi - (D(chi) / chi)**2
                                  - D(chi) / (2 * chi) * (D(a) / a - D(b) / b - 2 / r)) / a)
    bar_tt = (-D(b, 2) / (2 * b) + D(a) * D(b) / (4 * a * b) - D(b) / (r * b) + (1 - a / b) / r**2) / a
    Rtt = chi * (L / r + bar_tt + (D(chi, 2) / (2 * chi) - sp.Rational(3, 4) * (D(chi) / chi)**2
                                   - D(chi) / (4 * chi) * (D(a) / a - 3 * D(b) / b - 6 / r)) / a)
    gd = bGD if split else beta  # (H2): B is driven by d_t Delta^r of beta_GD
    return {
        'chi': adv(chi) + sp.Rational(2, 3) * chi * (al * K - dvb),
        'a': adv(a) + 2 * a * D(beta) - sp.Rational(2, 3) * a * dvb - 2 * al * a * Aa,
        'b': adv(b) + 2 * b * beta / r - sp.Rational(2, 3) * b * dvb + al * b * Aa,
        'K': adv(K) - lap + al * (sp.Rational(3, 2) * Aa**2 + K**2 / 3),
        'Aa': adv(Aa) - sp.Rational(2, 3) * hess_tf + sp.Rational(2, 3) * al * (Rrr - Rtt) + al * K * Aa,
        'L': rhs_L(beta, T_DLT),
        'alpha': (adv(al) if lapse_advective else 0) - 2 * al * K,
        # the full shift advects beta_GD and B (gbssn/rhs.cpp); the advective bracket of (G3)
        # removes B's driver term beta_GD d_r Delta^r exactly (the same stencil, gauge.hpp)
        'beta': sp.Rational(3, 4) * Bv + (adv(bGD) if driver_advective else 0),
        'B': (rhs_L(gd, 0) + adv(Bv)) if driver_advective else rhs_L(gd, T_DRV),
    }


FIELDS = sp.symbols('chi a b alpha beta_GD F')  # frozen values; F = beta_H / s^r


def principal_parts(normal='conformal', lapse_advective=True, driver_advective=False, split=True):
    """The principal symbol as {(row, col): {kind: coefficient}} with kind one of 'd1' (a first
    derivative, centred), 'd2' (second derivative), 'v' (undifferentiated: the coupling of a
    second-order field's equation to a first-order field), and the tags (advection stencils)."""
    fun = {n: sp.Function(n)(r) for n in ORDER}
    hat = {n: sp.Symbol(n + '_hat') for n in ORDER}
    E = sp.exp(sp.I * k * r)
    pert = {n: fun[n] + eps * hat[n] * E for n in ORDER}
    out = rhs(pert, normal, lapse_advective, driver_advective, split)
    frozen = dict(zip([fun[n] for n in ['chi', 'a', 'b', 'alpha', 'beta']] + [F], FIELDS))
    parts = {}
    for i, n in enumerate(ORDER):
        lin = sp.expand(sp.diff(out[n], eps).subs(eps, 0) / E)
        lin = sp.expand(sp.powsimp(lin))
        for j, m in enumerate(ORDER):
            c = lin.coeff(hat[m])
            # the power of i k that is principal: 1 within a block, 2 from first- to second-
            # order fields, 0 from second- to first-order fields
            want = {(True, True): 1, (False, False): 1, (False, True): 2, (True, False): 0}[
                (n in SECOND, m in SECOND)]
            poly = sp.Poly(sp.expand(c), k)
            assert poly.degree() <= want, (n, m, poly.degree())
            lead = sp.expand(poly.coeff_monomial(k**want) * (sp.I ** -want if want else 1))
            lead = lead.subs({D(f, 2): 0 for f in fun.values()}).subs({D(f): 0 for f in list(fun.values()) + [F]})
            lead = sp.expand(lead.subs(frozen))
            if lead == 0:
                continue
            entry = {}
            rest = lead
            for tag in TAGS:
                ct = sp.expand(lead).coeff(tag)
                if ct != 0:
                    entry[str(tag)] = sp.simplify(ct)
                    rest = sp.expand(rest - ct * tag)
            kind = {1: 'd1', 2: 'd2', 0: 'v'}[want]
            if sp.simplify(rest) != 0:
                entry[kind] = sp.simplify(rest)
            parts[(i, j)] = entry
    return parts


# ---- gbssn1d's 4th-order stencils (src/fd/stencils.hpp), as symbols at theta = k h ---------
W_D1 = {-2: 1 / 12, -1: -2 / 3, 1: 2 / 3, 2: -1 / 12}
W_D2 = {-2: -1 / 12, -1: 4 / 3, 0: -5 / 2, 1: 4 / 3, 2: -1 / 12}
W_PLUS = {-1: -1 / 4, 0: -5 / 6, 1: 3 / 2, 2: -1 / 2, 3: 1 / 12}  # leans towards +r (shift > 0)
W_MINUS = {-m: -w for m, w in W_PLUS.items()}


def stencil_symbol(weights, theta):
    return sum(w * np.exp(1j * m * theta) for m, w in weights.items())


def d1_stencil(kind, theta, beta_full, beta_gd):
    """Symbol of beta d_r by the stencil `kind` (gbssn1d's --driver-advection/--delta-advection
    names), for the speeds beta_full and beta_GD."""
    if kind in ('centred', 'matched'):
        return stencil_symbol(W_D1, theta)
    lean = beta_full if kind == 'upwind-full' else beta_gd
    return stencil_symbol(W_PLUS if lean > 0 else W_MINUS, theta)


class System:
    """The principal parts lambdified, for numbers."""

    def __init__(self, **options):
        self.options = options
        self.parts = principal_parts(**options)
        self.fns = {key: {kind: sp.lambdify(FIELDS, c, 'numpy') for kind, c in e.items()}
                    for key, e in self.parts.items()}

    def normal_inverse(self, fields, j):
        """1/s^r at point j of a profile (beta_H / s^r = F); 0 without the horizon shift."""
        a, chi = fields['a'][j], max(fields['chi'][j], 1e-300)
        return {'conformal': np.sqrt(a), 'unit': np.sqrt(a / chi), 'none': 0.0}[self.options['normal']]

    def continuum(self, vals):
        P = np.zeros((9, 9))
        for (i, j), e in self.fns.items():
            P[i, j] = sum(float(f(*vals)) for f in e.values())
        return P

    def discrete(self, vals, theta, driver='upwind-gd', delta='upwind-full', ko_sigma=0.1):
        """h times the semi-discrete symbol at theta (principal terms; h = the local spacing)."""
        chi, a, b, al, bgd, Fv = vals
        s = {'conformal': 1 / np.sqrt(a), 'unit': np.sqrt(max(chi, 0) / a), 'none': 0.0}[self.options['normal']]
        bfull = bgd + Fv * s
        d1 = stencil_symbol(W_D1, theta)
        sym = {'d1': d1, 'd2': stencil_symbol(W_D2, theta), 'v': 1.0,
               'T_adv': d1_stencil('upwind-full', theta, bfull, bgd),
               'T_dlt': d1_stencil(delta, theta, bfull, bgd),
               'T_drv': d1_stencil(driver, theta, bfull, bgd)}
        M = np.zeros((9, 9), dtype=complex)
        for (i, j), e in self.fns.items():
            M[i, j] = sum(float(f(*vals)) * sym[kind] for kind, f in e.items()
                          if not (kind == 'T_drv' and driver == 'matched'))
        if driver == 'matched':  # beta_GD d_r Delta = [beta d_r Delta]_(E6's stencil) - beta_H D_centred Delta
            M[ORDER.index('B'), ORDER.index('L')] += bfull * sym['T_dlt'] - (bfull - bgd) * d1
        M -= ko_sigma * np.sin(theta / 2)**6 * np.eye(9)  # Kreiss-Oliger, rate sigma/h at theta = pi
        return M

    def growth(self, vals, thetas=np.linspace(0.02, np.pi, 160), **kw):
        """max over theta of the largest real part of h x the semi-discrete eigenvalues, and
        the theta where it is taken."""
        best = (-np.inf, None)
        for th in thetas:
            g = np.max(np.linalg.eigvals(self.discrete(vals, th, **kw)).real)
            if g > best[0]:
                best = (g, th)
        return best


def read_profiles(path):
    """The blocks of a gbssn1d profiles.dat: [(t, {column: array})]."""
    names, blocks, rows, t = None, [], [], None
    for line in open(path):
        if line.startswith('# r '):
            names = line[2:].split()
        elif line.startswith('# t ='):
            if rows:
                blocks.append((t, np.array(rows)))
            rows, t = [], float(line.split('=')[1].split()[0])
        elif line.strip() and not line.startswith('#'):
            rows.append([float(x) for x in line.split()])
    if rows:
        blocks.append((t, np.array(rows)))
    return [(t, {n: d[:, i] for i, n in enumerate(names)}) for t, d in blocks]


# ---- predictions on a run's fields ----------------------------------------------------------
AMPLIFICATION = np.log(1e16)  # round-off (1e-16) to order one: the blow-up's e-folds


def growth_profile(system, fields, rmin, rmax, stride, **kw):
    """[(r, h x growth rate)] at every stride-th point with rmin < r < rmax."""
    out = []
    thetas = np.linspace(np.pi / 24, np.pi, 24)
    for j in range(0, len(fields['r']), stride):
        rr = fields['r'][j]
        if not rmin < rr < rmax:
            continue
        vals = (fields['chi'][j], fields['a'][j], fields['b'][j], fields['alpha'][j],
                fields['beta_GD'][j], fields['beta_H'][j] * system.normal_inverse(fields, j))
        out.append((rr, system.growth(vals, thetas=thetas, **kw)[0]))
    return out


def predict_onset(system, blocks, spacing, rmin=0.05, rmax=6.0, stride=2, **kw):
    """The time at which the grid-scale mode has grown by AMPLIFICATION e-folds, integrating
    max_r growth(r, t) / spacing(r) over the blocks (held constant over each block), and the
    radius of the largest rate then; None if it never does."""
    total, prev_t, prev_rate, prev_r = 0.0, None, 0.0, None
    for t, fields in blocks:
        prof = growth_profile(system, fields, rmin, rmax, stride, **kw)
        rates = [(g / spacing(rr), rr) for rr, g in prof]
        rate, r_at = max(rates) if rates else (0.0, None)
        if prev_t is not None and prev_rate > 0:
            dt = t - prev_t
            if total + prev_rate * dt >= AMPLIFICATION:
                return prev_t + (AMPLIFICATION - total) / prev_rate, prev_r, prev_rate
            total += prev_rate * dt
        prev_t, prev_rate, prev_r = t, max(rate, 0.0), r_at
    return None, None, None


# ---- self-checks and predictions that could fail ---------------------------------------------
def check():
    """Exit status 1 if any check fails."""
    failures = []

    def report(ok, label):
        print(('PASS  ' if ok else 'FAIL  ') + label, flush=True)
        if not ok:
            failures.append(label)

    rng = np.random.default_rng(1)
    published = System(normal='conformal', lapse_advective=True, driver_advective=False, split=True)
    advective = System(normal='conformal', lapse_advective=True, driver_advective=True, split=True)
    # 1. continuum speeds against the known families: light beta +- alpha sqrt(chi/a), 1+log
    #    beta +- sqrt(2 alpha chi/a) (both with the full shift), the shift's zero speed
    for trial in range(5):
        chi, a, b = rng.uniform(0.2, 1.0), rng.uniform(0.8, 1.3), rng.uniform(0.8, 1.3)
        al, bgd, Fv = rng.uniform(0.2, 0.9), rng.uniform(0.0, 0.5), rng.uniform(-0.2, 0.2)
        vals = (chi, a, b, al, bgd, Fv)
        bfull = bgd + Fv / np.sqrt(a)
        ev = np.linalg.eigvals(published.continuum(vals))
        want = [bfull + al * np.sqrt(chi / a), bfull - al * np.sqrt(chi / a),
                bfull + np.sqrt(2 * al * chi / a), bfull - np.sqrt(2 * al * chi / a), bfull, 0.0]
        found = all(np.min(np.abs(ev - w)) < 1e-9 for w in want)
        real = np.max(np.abs(ev.imag)) < 1e-12
        _, V = np.linalg.eig(published.continuum(vals))
        report(found and real and np.linalg.cond(V) < 1e6,
               f'continuum, published gauge, point {trial}: light and 1+log speeds with the full '
               f'shift, real speeds, cond(eigenvectors) {np.linalg.cond(V):.3g}')
    # 2. the semi-discrete scheme on a stretching background (beta_GD > 0, beta_H < 0, as at
    #    r = 1.5M of a 1+log trumpet stretched to 1.5M): the published stencil grows at the
    #    grid scale; the matched and centred ones, the advective driver, and beta_H = 0 do not
    vals = (0.55, 1.0, 1.0, 0.5, 0.14, -0.09)
    g_pub, th = published.growth(vals, driver='upwind-gd')
    report(g_pub > 0.05 and th > 0.9 * np.pi,
           f'upwind-gd driver term with beta_H: grows at the grid scale, h x rate {g_pub:.3f} at theta {th:.2f}')
    for label, system, kw, v in [
            ('matched driver term', published, {'driver': 'matched'}, vals),
            ('centred driver term', published, {'driver': 'centred'}, vals),
            ('advective driver', advective, {}, vals),
            ('upwind-gd without beta_H', published, {'driver': 'upwind-gd'}, vals[:5] + (0.0,))]:
        g = system.growth(v, **kw)[0]
        report(g < 1e-9, f'{label}: no growth (h x rate {g:.2e})')
    # 3. the growth is the stencil's, not the continuum's: without dissipation the matched term
    #    is still stable to 1e-4 / h, the published one is not
    g0 = published.growth(vals, driver='matched', ko_sigma=0.0)[0]
    report(g0 < 1e-4, f'matched driver term without dissipation: h x rate {g0:.2e} < 1e-4')
    return 1 if failures else 0


def grid_mode(system, vals, dtheta=1e-3, **kw):
    """(h x growth rate, group velocity) of the fastest-growing eigenvalue at theta = pi: the
    grid-scale mode. The group velocity -d Im(lambda)/dk is taken by following that eigenvalue
    to theta = pi - dtheta."""
    ev = np.linalg.eigvals(system.discrete(vals, np.pi, **kw))
    lam = ev[np.argmax(ev.real)]
    ev2 = np.linalg.eigvals(system.discrete(vals, np.pi - dtheta, **kw))
    lam2 = ev2[np.argmin(np.abs(ev2 - lam))]
    return lam.real, (lam2.imag - lam.imag) / dtheta


def predict_onset_rays(system, blocks, spacing, rmin=0.3, rmax=4.0, rays=40, dt=0.02, **kw):
    """The grid-scale mode followed along rays dr/dt = its group velocity, from rays starting
    at rmin ... rmax at t = 0, its amplitude growing at rate / spacing(r); the first ray to
    grow AMPLIFICATION e-folds gives (t_onset, r_onset). The fields at time t are the last
    block at or before t."""
    times = [t for t, _ in blocks]

    def fields_at(t):
        return blocks[max(0, np.searchsorted(times, t, side='right') - 1)][1]

    def vals_at(f, rr):
        j = min(np.searchsorted(f['r'], rr), len(f['r']) - 1)
        return (f['chi'][j], f['a'][j], f['b'][j], f['alpha'][j], f['beta_GD'][j],
                f['beta_H'][j] * system.normal_inverse(f, j))

    r = np.linspace(rmin, rmax, rays)
    amp = np.zeros(rays)
    t = 0.0
    while t < times[-1]:
        f = fields_at(t)
        for i in range(rays):
            g, vg = grid_mode(system, vals_at(f, r[i]), **kw)
            amp[i] += max(g, 0.0) / spacing(r[i]) * dt
            r[i] = max(r[i] + vg * dt, 0.0)
        t += dt
        if amp.max() >= AMPLIFICATION:
            return t, r[np.argmax(amp)]
    return None, None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--check', action='store_true', help='self-checks and predictions')
    ap.add_argument('--profiles', help="a run's profiles.dat: the growth rate of the semi-discrete "
                    'scheme on its fields, and the predicted onset of a blow-up')
    ap.add_argument('--driver-advection', default='upwind-gd',
                    choices=['upwind-gd', 'upwind-full', 'centred', 'matched'])
    ap.add_argument('--delta-advection', default='upwind-full',
                    choices=['upwind-gd', 'upwind-full', 'centred'])
    ap.add_argument('--normal', default='conformal', choices=['conformal', 'unit'])
    ap.add_argument('--advective-shift', action='store_true')
    ap.add_argument('--ko-sigma', type=float, default=0.1)
    ap.add_argument('--continuum', action='store_true',
                    help="with --profiles: the continuum speeds on the run's fields (largest "
                    "imaginary part, condition number of the eigenvectors) instead of the onset")
    ap.add_argument('--spacing-factor', type=float, nargs='+', default=[1.0],
                    help="predict for grids whose spacings are these multiples of the profile "
                    "run's (e.g. 0.5: twice the N)")
    args = ap.parse_args()
    if args.check:
        sys.exit(check())
    if not args.profiles:
        ap.error('give --check or --profiles')
    system = System(normal=args.normal, lapse_advective=True,
                    driver_advective=args.advective_shift, split=True)
    blocks = read_profiles(args.profiles)
    r = blocks[0][1]['r']
    widths = np.gradient(r)
    kw = dict(driver=args.driver_advection, delta=args.delta_advection, ko_sigma=args.ko_sigma)
    if args.continuum:
        print('# t max|Im speed| cond(eigenvectors) over 1M <= r <= 1.8M, largest cond over '
              '0.3M <= r <= 4M and its r')
        for t, f in blocks:
            conds, imag = [], 0.0
            for j, rr in enumerate(f['r']):
                if not 0.3 <= rr <= 4.0:
                    continue
                vals = (f['chi'][j], f['a'][j], f['b'][j], f['alpha'][j], f['beta_GD'][j],
                        f['beta_H'][j] * system.normal_inverse(f, j))
                ev, V = np.linalg.eig(system.continuum(vals))
                imag = max(imag, float(np.max(np.abs(ev.imag))))
                conds.append((np.linalg.cond(V), rr))
            band = [c for c, rr in conds if 1.0 <= rr <= 1.8]
            worst = max(conds)
            print(f'{t:g} {imag:.2e} {min(band):.3g}-{max(band):.3g} {worst[0]:.3g} {worst[1]:.3g}')
        return
    print('# spacing_factor t_onset r_max_rate rate_at_onset t_onset_ray r_onset_ray   (e-folds '
          f'to blow-up: {AMPLIFICATION:.1f}; "-" none predicted)')
    for s in args.spacing_factor:
        spacing = lambda rr: np.interp(rr, r, widths) * s  # noqa: E731
        t_on, r_on, rate = predict_onset(system, blocks, spacing, **kw)
        t_ray, r_ray = predict_onset_rays(system, blocks, spacing, **kw)
        fmt = lambda *v: ' '.join('-' if x is None else f'{x:.4g}' for x in v)  # noqa: E731
        print(f'{s:g} ' + fmt(t_on, r_on, rate, t_ray, r_ray))


if __name__ == '__main__':
    main()
