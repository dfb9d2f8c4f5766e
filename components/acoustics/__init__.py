"""Acoustics models (installed as lpc_mdo.components.acoustics).

Rotor noise at an observer (paper Sec. III.E; docs theory/acoustics):

- ``observer``: ObserverPositionComp, ObserverGeometryComp (distances, Doppler, azimuth).
- ``loads``: LoadFourierComp (paper eqs. 19-20), HoverLoadDistributionComp (assumed hover shape).
- ``tonal``: SearsGustLoadsComp, LowsonLoadingNoiseComp (Lowson-Ollerhead loading noise).
- ``thickness``: BarryMagliozziThicknessComp.
- ``broadband``: GillLeeBroadbandComp (paper eq. 22).
- ``a_weighting``: a_weighting(), AWeightingComp.
- ``total``: TotalNoiseComp (energetic sums, paper eq. 21 levels).
- ``common``: constants (p_ref, level floor), band centres, radial quadrature, checks.

The assembly is lpc_mdo.groups.acoustics.RotorNoiseGroup.
"""
