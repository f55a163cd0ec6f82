"""The measured data sets of ../shared/data (relative to the repository
root): skipped with the reason when absent, failing under
ASPERITY_REQUIRE_ALL=1."""

import pytest

import asperity

from conftest import assert_same, cli_json, shared_data

AGILENT_AREA = [27.3136, 152.6988585, -494.1823171]
XP_AREA = [24.6954, 395.7700812, -16.13158277]


@pytest.mark.parametrize(
    "name, area, tolerance",
    [
        # tests/indentation.rs: within each file's tip-calibration error of 69.6 GPa.
        ("fused_silica_berkovich_agilent_calibration_test001.csv", AGILENT_AREA, 0.116),
        ("fused_silica_berkovich_XP_test001.csv", XP_AREA, 0.060),
    ],
)
def test_fused_silica(name, area, tolerance):
    path = shared_data("indentation", name)
    r = asperity.analyze_indentation(str(path), indenter="berkovich", area=area, nu_sample=0.18)
    assert abs(r["reduced_modulus"] / 69.6e9 - 1) <= tolerance
    cli = cli_json("indent", str(path), "--indenter", "berkovich", "--area", ",".join(map(repr, area)), "--nu-sample", "0.18", "--json")
    assert_same(cli, r)


@pytest.mark.parametrize("name", ["dektak1_stylus_linescan.csv", "hommel_hfm1_stylus_linescan.csv", "afm_dimension_icon_di3_zsensor_map.csv"])
def test_measured_profiles_equal_cli(name):
    path = shared_data("profiles", name)
    r = asperity.analyze_profile_file(str(path))
    cli = cli_json("profile", str(path), "--json")
    assert_same(cli, r)
