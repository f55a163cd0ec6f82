"""Materials, rescaling, surfaces and statistics against the reference
values of REFERENCE.md and the Rust tests."""

import math

import numpy as np
import pytest

import asperity

from conftest import assert_same, cli_json, example


def test_materials_reference_values():
    # Copper on copper: E* = E/(2(1 - ν²)) = 68.65 GPa; C_NS(0.355) = 1.017376.
    assert asperity.effective_modulus(120e9, 0.355, 120e9, 0.355) == pytest.approx(120e9 / (2 * (1 - 0.355**2)), rel=1e-14)
    assert asperity.effective_modulus(1e9, 0.5, math.inf, 0.2) == pytest.approx(1e9 / 0.75, rel=1e-14)
    assert asperity.no_slip_factor(0.355) == pytest.approx(1.017376, rel=1e-6)
    assert asperity.no_slip_factor(0.5) == 1.0
    # Weir: diamond (111) 2.05615 J/m² with K = 1/40.
    assert asperity.weir_surface_energy(1.99e-26, 3500, 1164e9, 0.079) == pytest.approx(2.05615, rel=1e-5)
    assert asperity.weir_surface_energy(1.99e-26, 3500, 1164e9, 0.079, prefactor="three_over_mn") == pytest.approx(2.05615 * 40 / 24, rel=1e-5)
    # Hamaker: A = 2.7e-19 J at 2.56 Å gives 0.10928 J/m².
    assert asperity.hamaker_work_of_adhesion(2.7e-19, 2.56e-10) == pytest.approx(0.10928, rel=1e-4)
    assert asperity.pair_work_of_adhesion(0.5, 0.5) == pytest.approx(1.0, rel=1e-15)
    m = asperity.Material(120e9, 0.355)
    assert m.contact_modulus(m) == asperity.effective_modulus(120e9, 0.355, 120e9, 0.355)
    assert asperity.maugis_parameter(1e-6, 0.1, 1e10, 1e8) == pytest.approx(
        2 * 1e8 * (1e-6 / (math.pi * 0.1 * (4 / 3 * 1e10) ** 2)) ** (1 / 3), rel=1e-14)


def test_rescaling_hertz_case():
    # κ = 1, d = 2 (Hertz): load ∝ depth^(3/2), depth ∝ λ^(1/3) at fixed load.
    r = asperity.Rescaling.sphere(1.0)
    assert r.load_depth_exponent() == pytest.approx(1.5, rel=1e-15)
    known = asperity.KnownSolution(load=1e-3, depth=1e-7, radius=1e-5)
    assert r.depth(8.0, 1e-3, known) == pytest.approx(1e-7 * 8.0 ** (1 / 3), rel=1e-13)
    assert asperity.lambda_spheres(2e-6, 1e-6) == pytest.approx(2.0, rel=1e-15)
    assert asperity.d_from_unloading_slope(1.5) == pytest.approx(2.0, rel=1e-14)


def test_synthetic_indentation_curve_equals_cli():
    path = example("data", "synthetic_berkovich.csv")
    r = asperity.analyze_indentation(str(path), indenter="berkovich", nu_sample=0.17)
    # tests/indentation.rs: the synthetic curve reads back E_r = 69.6 GPa, H = 9 GPa.
    assert r["reduced_modulus"] == pytest.approx(69.6e9, rel=1e-4)
    assert r["hardness"] == pytest.approx(9e9, rel=1e-3)
    cli = cli_json("indent", str(path), "--indenter", "berkovich", "--nu-sample", "0.17", "--json")
    assert_same(cli, r)
    # The Oliver-Pharr options as the CLI's flags.
    r = asperity.analyze_indentation(str(path), nu_sample=0.17, beta=1.05, epsilon=0.72, unloading_window=(0.5, 0.95))
    cli = cli_json("indent", str(path), "--nu-sample", "0.17", "--beta", "1.05", "--epsilon", "0.72",
                   "--fit-window", "0.5,0.95", "--json")
    assert_same(cli, r)
    with pytest.raises(asperity.Error, match="unloading_window"):
        asperity.analyze_indentation(str(path), unloading_window=(0.5,))
    with pytest.raises(asperity.Error, match="unloading_window"):
        asperity.analyze_indentation(str(path), unloading_window=(0.9, 0.5))
    c = asperity.read_indentation_curve(str(path))
    arrays = asperity.analyze_indentation(depth=c["depth"], load=c["load"], nu_sample=0.17, detect_segments=True)
    assert arrays["reduced_modulus"] == pytest.approx(69.6e9, rel=2e-2)


def test_profile_parameters_equal_cli():
    path = example("data", "synthetic_profile.csv")
    for detrend, cutoff in [("linear", None), ("quadratic", 0.4e-3), ("none", None)]:
        args = ["profile", str(path), "--json", "--detrend", detrend]
        if cutoff is not None:
            args += ["--cutoff", repr(cutoff)]
        cli = cli_json(*args)
        f = asperity.analyze_profile_file(str(path), detrend=detrend, cutoff=cutoff)
        assert_same(cli, f)
        p = asperity.read_profile(str(path))
        raw = np.loadtxt([l for l in path.read_text().splitlines() if l and l[0] not in "#x"], delimiter=",")
        arrays = asperity.profile_parameters(raw[:, 0].copy(), raw[:, 1].copy(), detrend=detrend, cutoff=cutoff)
        del cli["file"], cli["plots"], cli["format"], cli["channel"]
        assert_same(cli, arrays)
        assert p["z"].shape[0] == cli["points_read"]
    # Keys promised by the issue.
    for k in ["Ra", "Rq", "Rsk", "Rku", "RDq", "Rp", "Rv", "Rz", "Rt", "RSm", "Rc"]:
        assert k in arrays
    for k in ["Rk", "Rpk", "Rvk", "Mr1", "Mr2", "convention"]:
        assert k in arrays


def test_profile_conventions():
    # Sections of different amplitude: ISO 4287 averages the section Rq,
    # ISO 21920-2 takes Rq over the evaluation length.
    per, dx = 100, 1e-6
    j = np.arange(5 * 4 * per)
    z = (1.0 + j // (4 * per)) * 1e-6 * np.sin(2 * np.pi * j / per)
    new = asperity.profile_parameters(dx, z, detrend="none", cutoff=None)
    assert new["convention"] == "ISO 21920-2:2021"
    assert new["Rq"] == pytest.approx(math.sqrt(11 / 2) * 1e-6, rel=1e-9)
    old = asperity.profile_parameters(dx, z, detrend="none", convention="iso4287")
    assert old["convention"] == "ISO 4287:1997"
    assert old["Rq"] == pytest.approx(new["Rq"], rel=1e-12)  # one section: equal
    with pytest.raises(ValueError, match="convention"):
        asperity.profile_parameters(dx, z, convention="iso9999")


def test_profile_of_a_sine():
    n, dx = 4096, 1e-7
    x = np.arange(n) * dx
    a, wl = 1e-6, n * dx / 8
    z = a * np.sin(2 * np.pi * x / wl)
    p = asperity.profile_parameters(x, z, detrend="none")
    assert p["Rq"] == pytest.approx(a / math.sqrt(2), rel=1e-9)
    assert p["Ra"] == pytest.approx(2 * a / math.pi, rel=1e-4)
    assert p["RSm"] == pytest.approx(wl, rel=1e-6)
    assert p["psd_hurst_exponent"] is None
    same = asperity.profile_parameters(dx, z, detrend="none")
    assert same["Rq"] == p["Rq"]
    s = asperity.psd(z, dx)
    assert np.sum(s["psd"]) * s["dq"] == pytest.approx(np.mean(z**2), rel=1e-9)
    ac = asperity.acf(z, dx)
    assert ac["acf"][0] == pytest.approx(np.mean(z**2), rel=1e-9)


def test_generators_and_map():
    z = asperity.self_affine_profile(8192, 1e-6, 0.7, 2e-6, seed=3)
    assert np.sqrt(np.mean(z**2)) == pytest.approx(2e-6, rel=1e-12)
    assert np.array_equal(z, asperity.self_affine_profile(8192, 1e-6, 0.7, 2e-6, seed=3))
    assert asperity.hurst_fit(z, 1e-6)["hurst"] == pytest.approx(0.7, abs=0.1)
    m = asperity.self_affine_map(64, 32, 1e-6, 1e-6, 0.8, 1e-6, seed=1)
    assert m.shape == (32, 64)
    p = asperity.map_parameters(m, 1e-6, detrend="none")
    assert p["Sq"] == pytest.approx(1e-6, rel=1e-9)
    assert p["nx"] == 64 and p["ny"] == 32
    w = asperity.weierstrass_mandelbrot_profile(1024, 1e-6, 1.5, 1.5, 1e-6, seed=2)
    assert w.shape == (1024,)
    c = asperity.cantor_borodich_profile(1e-3, 1000, 2, 0.3, 0.7, 1e-6, 6)
    assert c.shape == (1000,)


def test_greenwood_williamson_closed_form():
    n, radius, e, sigma = 1e6, 1e-4, 1e11, 1e-6
    gw = asperity.GreenwoodWilliamson(n, radius, e, asperity.HeightDistribution.gaussian(sigma))
    d = np.array([0.0, 1e-6, 2e-6])
    r = gw.response(d)
    f32 = asperity.gaussian_tail_moment(1.5, d / sigma)
    assert np.allclose(r["load"], 4 / 3 * n * e * math.sqrt(radius) * sigma**1.5 * f32, rtol=1e-12)
    assert r["contacts"][0] == pytest.approx(n / 2, rel=1e-12)
    for i, di in enumerate(d):
        assert gw.load(float(di)) == r["load"][i]
    sol = gw.separation_at_load(float(r["load"][1]))
    assert sol["separation"] == pytest.approx(1e-6, rel=1e-9)
    assert asperity.deformation_regime(asperity.plasticity_index(1e11, 1e9, 1e-6, 1e-4)) == "plastic"


def test_moments_hurst_and_maps():
    # Moments from the derivatives: a sine's slope and curvature variances.
    a, wl, dx = 1e-6, 1e-4, 5e-7
    x = np.arange(2000) * dx
    z = a * np.sin(2 * np.pi * x / wl)
    m = asperity.spectral_moments(z, dx)
    q = 2 * np.pi / wl
    assert m["m2"] == pytest.approx(a * a / 2 * q * q, rel=3e-3)
    assert m["m4"] == pytest.approx(a * a / 2 * q**4, rel=3e-3)
    assert asperity.psd(z, dx)["m2_rectangular_window"] == pytest.approx(a * a / 2 * q * q, rel=1e-9)
    # The Hurst fit with its uncertainty and the band from the data.
    zs = asperity.self_affine_profile(1 << 16, 1e-8, 0.8, 1e-6, seed=2)
    f = asperity.hurst_fit(zs, 1e-8)
    assert f["hurst"] == pytest.approx(0.8, abs=0.02)
    assert 0 < f["hurst_uncertainty"] < 0.01
    p = asperity.profile_parameters(1e-8, zs, detrend="none")
    assert p["psd_hurst_exponent"] == f["hurst"] and p["psd_fit_reason"] is None
    assert p["m2"] == pytest.approx(p["RDq"] ** 2, rel=1e-9)
    # Maps: 2-D PSD (Parseval), ACF, isotropy, scale dependence, areal filter.
    mp = asperity.self_affine_map(64, 48, 1e-8, 1e-8, 0.7, 1e-8, seed=4)
    g = asperity.psd_2d(mp, 1e-8)
    assert g["psd"].shape == (48, 64)
    assert g["psd"].sum() * g["dqx"] * g["dqy"] == pytest.approx(np.mean((mp - mp.mean()) ** 2), rel=1e-9)
    ac = asperity.acf_2d(mp, 1e-8)
    assert ac["acf"].shape == (95, 127)
    assert ac["acf"][47, 63] == pytest.approx(np.mean((mp - mp.mean()) ** 2), rel=1e-9)
    iso = asperity.isotropy(mp, 1e-8)
    assert 0 < iso["gradient_ratio"] <= 1
    sd = asperity.scale_dependent(mp, 1e-8)
    assert len(sd["along_x"]["scale"]) == len(sd["along_x"]["slope_rms"])
    assert asperity.scale_dependent(zs, 1e-8)["slope_rms"][0] > 0
    fl = asperity.areal_gaussian_filter(mp, 1e-8, 1e-7)
    assert fl["roughness"].shape == (48 - 10, 64 - 10) and fl["first_index"] == (5, 5)
    mm = asperity.map_parameters(mp, 1e-8, cutoff=1e-7)
    assert mm["nx"] == 54 and "isotropy" in mm and "psd_radial" in mm
    with pytest.raises(asperity.Error):
        asperity.areal_gaussian_filter(mp, 1e-8, 1e-5)
