# SPDX-License-Identifier: GPL-3.0-or-later
"""The material pairs and regimes the studies solve, and what the core says of them (E', the
cap H = 2.84 S_y of the softer solid: roughcontact.ContactMaterials).

Pairs: handbook values (E [Pa], nu, S_y [Pa]) of common engineering grades. A regime is elastic
(steel on steel; an answer in x = p/(E' h') holds for every pair) or capped at a pair's H.
"""
STEEL = (200e9, 0.3, 0.5e9)  # a medium-carbon steel
ALUMINIUM = (68.9e9, 0.33, 276e6)  # 6061-T6
COPPER = (117e9, 0.34, 70e6)  # annealed (half-hard copper is about 250 MPa)
HARD_STEEL = (205e9, 0.29, 1.2e9)  # AISI 4340 quenched and tempered (about 38 HRC)

# (key, label, solid 1, solid 2)
PAIRS = [
    ("steelSteel", "steel on steel", STEEL, STEEL),
    ("aluminiumSteel", "aluminium 6061-T6 on steel", ALUMINIUM, STEEL),
    ("copperCopper", "annealed copper on copper", COPPER, COPPER),
    ("hardSteel", "hardened steel on hardened steel (4340 Q&T)", HARD_STEEL, HARD_STEEL),
]

# (key, label, the pair's key or None: elastic)
REGIMES = [("elastic", "elastic", None)] + [(key, f"capped: {label}", key) for key, label, _, _ in PAIRS]


def pair_of(key):
    return next(p for p in PAIRS if p[0] == key)


def regime_of(key):
    return next(r for r in REGIMES if r[0] == key)


class Pair:
    """Two solids as the core sees them: E' [Pa], H [Pa] (None without a cap), and the CLI's
    arguments of the materials."""

    def __init__(self, ctx, a, b, capped):
        rc = ctx.rc()
        m = rc.ContactMaterials.pair(rc.Material(E=a[0], nu=a[1], Sy=a[2]), rc.Material(E=b[0], nu=b[1], Sy=b[2]))
        self.materials = m  # the core's ContactMaterials (a multi-scale model's)
        self.Eprime = m.reduced_modulus
        self.hardness = m.hardness if capped else None
        self.arguments = ["--E", f"{a[0]:.6g},{b[0]:.6g}", "--nu", f"{a[1]:.6g},{b[1]:.6g}"] + (
            ["--Sy", f"{a[2]:.6g},{b[2]:.6g}"] if capped else [])


def regime_pair(ctx, regime_key):
    """The Pair of a regime: steel on steel, elastic, or the regime's pair capped."""
    key = regime_of(regime_key)[2]
    if key is None:
        return Pair(ctx, STEEL, STEEL, False)
    _, _, a, b = pair_of(key)
    return Pair(ctx, a, b, True)
