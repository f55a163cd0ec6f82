//! The Gaussian height integrals `F_q(h) = ∫_h^∞ (s − h)^q φ(s) ds` of the
//! Greenwood–Williamson model (thesis (1-29), (1-30); REFERENCE.md §3, §8):
//! the printed table, 30-digit reference values, an independent quadrature on
//! a dense grid, far tails and very negative h.

use approx::assert_relative_eq;
use asperity::statistics::gaussian::{
    f0, f1, f1_2, f3_2, f5_2, tail_moment, tail_moment_quadrature, RELATIVE_ACCURACY,
};
use asperity::Error;

// Reference values: `F_q(h) = Γ(q+1) e^{−h²/4} D_{−q−1}(h)/√(2π)` with the
// parabolic-cylinder function D of mpmath 1.3.0 at 40 digits (independent of
// the library's trapezoidal sums and tanh–sinh quadrature), rounded to the
// nearest f64 by this script:
//
//     from mpmath import mp, mpf, gamma, exp, sqrt, pi, pcfd
//     mp.dps = 40
//     def F(n, h):
//         h = mpf(h); n = mpf(n)
//         return gamma(n+1)/sqrt(2*pi)*exp(-h*h/4)*pcfd(-n-1, h)
//     def r(x): return repr(float(x))
//     hs = [mpf(i)/4 for i in range(-12, 25)] + [mpf(x) for x in (-30, -25, -20, -15, -10, -6, -4, 7, 8, 10, 12, 15, 20, 25, 30, 35, 37)]
//     hs = sorted(hs)
//     print("const HALF_INTEGER: &[(f64, f64, f64, f64)] = &[")
//     for h in hs:
//         print("    (%s, %s, %s, %s)," % (r(h), r(F(0.5,h)), r(F(1.5,h)), r(F(2.5,h))))
//     print("];")
//     print("const GENERAL: &[(f64, f64, f64)] = &[")
//     for qs, qq in [('4.0 / 3.0', mpf(4)/3), ('1.25', mpf('1.25')), ('1.056', mpf('1.056')), ('0.7', mpf('0.7')), ('3.0', mpf(3)), ('2.0', mpf(2)), ('10.0', mpf(10))]:
//         for h in [-40, -5, -1, 0, 0.5, 1, 3, 6]:
//             print("    (%s, %s, %s)," % (qs, r(mpf(h)), r(F(qq,h))))
//     print("];")

const HALF_INTEGER: &[(f64, f64, f64, f64)] = &[
    (
        -30.0,
        5.476464054531876,
        164.38524685803847,
        4939.772101822951,
    ),
    (
        -25.0,
        4.998998493654489,
        125.07502255276192,
        3134.3740615595298,
    ),
    (
        -20.0,
        4.470735115283984,
        89.52661109945504,
        1797.2383246620268,
    ),
    (
        -15.0,
        3.870822616820672,
        58.19165599424329,
        878.6810738388804,
    ),
    (
        -10.0,
        3.1582867358815188,
        31.741587709726318,
        322.15330720108545,
    ),
    (-6.0, 2.44074445142828, 14.850864472910896, 92.7663035146078),
    (
        -4.0,
        1.9832298897597236,
        8.189959426789363,
        35.734682541797035,
    ),
    (
        -3.0,
        1.7041320019204507,
        5.418377276511696,
        18.811329832415762,
    ),
    (
        -2.75,
        1.6254561345887655,
        4.793939304792976,
        15.621517290063831,
    ),
    (
        -2.5,
        1.5418904995431508,
        4.199895952398184,
        12.812575630310187,
    ),
    (
        -2.25,
        1.4525746382753877,
        3.638240136467941,
        10.364902264465949,
    ),
    (
        -2.0,
        1.3566405981393808,
        3.111292885687599,
        8.257546668584268,
    ),
    (
        -1.75,
        1.2533840459260628,
        2.6216767017160216,
        6.468010296892133,
    ),
    (
        -1.5,
        1.142514886340674,
        2.1722094005070636,
        4.972086430271606,
    ),
    (
        -1.25,
        1.0244539908026309,
        1.7656936537820231,
        3.743798053431475,
    ),
    (
        -1.0,
        0.9006029312703163,
        1.4045974704739523,
        2.7555018673794267,
    ),
    (
        -0.75,
        0.7734860199222885,
        1.0906541678945676,
        1.9782196558043583,
    ),
    (
        -0.5,
        0.6466694535032851,
        0.8244484201857112,
        1.3822283903477832,
    ),
    (
        -0.25,
        0.5244123561093368,
        0.6050826799836165,
        0.9378892041599093,
    ),
    (
        0.0,
        0.4110894793312293,
        0.4300199936622598,
        0.6166342189968439,
    ),
    (
        0.25,
        0.310513512489138,
        0.29516724046157017,
        0.3919784586183145,
    ),
    (
        0.5,
        0.2253355816973116,
        0.19520360374379064,
        0.2404015706740721,
    ),
    (
        0.75,
        0.15668774956470094,
        0.12409268046780335,
        0.14196211399619887,
    ),
    (
        1.0,
        0.1041536753078577,
        0.07566817739097507,
        0.08056233557081147,
    ),
    (
        1.25,
        0.06604636703277829,
        0.044170735496362815,
        0.04385613117871391,
    ),
    (
        1.5,
        0.039881517654695796,
        0.024639480307483735,
        0.02286305602081809,
    ),
    (
        1.75,
        0.02289594621254856,
        0.013112911644412651,
        0.011396323941100697,
    ),
    (
        2.0,
        0.012480040296439067,
        0.006648177623587093,
        0.005423705197484414,
    ),
    (
        2.25,
        0.006451034146934628,
        0.0032068043757752978,
        0.002461241374907522,
    ),
    (
        2.5,
        0.0031590230326521717,
        0.0014699382395379915,
        0.0010636889501332788,
    ),
    (
        2.75,
        0.0014641973550413403,
        0.0006396276495975517,
        0.00043731999616874307,
    ),
    (
        3.0,
        0.0006418504393485508,
        0.0002639675542694673,
        0.00017087299621442438,
    ),
    (
        3.25,
        0.0002659273168148375,
        0.00010323011667738047,
        6.339309602076967e-05,
    ),
    (
        3.5,
        0.00010407145290773235,
        3.8227077760961094e-05,
        2.2312407198234688e-05,
    ),
    (
        3.75,
        3.845177088673138e-05,
        1.3395389355621701e-05,
        7.444946246515686e-06,
    ),
    (
        4.0,
        1.340666992449641e-05,
        4.439155958539252e-06,
        2.353381052587606e-06,
    ),
    (
        4.25,
        4.4093291823807045e-06,
        1.3905112557080341e-06,
        7.043209368119122e-07,
    ),
    (
        4.5,
        1.3674721507435336e-06,
        4.1149986385075114e-07,
        1.9945883878692032e-07,
    ),
    (
        4.75,
        3.9978225180533093e-07,
        1.1500031647973259e-07,
        5.342187442926659e-08,
    ),
    (
        5.0,
        1.1014563207789281e-07,
        3.033850561878485e-08,
        1.3525920022914967e-08,
    ),
    (
        5.25,
        2.8591866684611715e-08,
        7.552717488829722e-09,
        3.23603321056153e-09,
    ),
    (
        5.5,
        6.99122414538976e-09,
        1.773735478316126e-09,
        7.312910873459463e-10,
    ),
    (
        5.75,
        1.6099534457550723e-09,
        3.928498413166207e-10,
        1.560435810620394e-10,
    ),
    (
        6.0,
        3.490963471387392e-10,
        8.203580589815166e-11,
        3.142968531919884e-11,
    ),
    (
        7.0,
        4.2158901308053166e-13,
        8.621388970723251e-14,
        2.888629167016989e-14,
    ),
    (
        8.0,
        1.9240743960372775e-16,
        3.4783997922186915e-17,
        1.0339176028096326e-17,
    ),
    (
        10.0,
        2.117479299141611e-24,
        3.101206508673169e-25,
        7.501244003924727e-26,
    ),
    (
        12.0,
        4.517923976364681e-34,
        5.553217240644714e-35,
        1.1302527577336461e-35,
    ),
    (
        15.0,
        8.367907053311701e-52,
        8.277318989102985e-53,
        1.3588209631307255e-53,
    ),
    (
        20.0,
        5.444937888305464e-90,
        4.0585550792627845e-91,
        5.029667393262765e-92,
    ),
    (
        25.0,
        5.410317004946347e-139,
        3.2333284049509563e-140,
        3.21544950421295e-141,
    ),
    (
        30.0,
        7.9314845871808665e-199,
        3.9547990870299806e-200,
        3.282961968135747e-201,
    ),
    (
        35.0,
        1.6839130324341382e-269,
        7.202113670874815e-271,
        5.129763845021761e-272,
    ),
    (
        37.0,
        8.336543877936438e-301,
        3.3735350268342336e-302,
        2.2736217617994173e-303,
    ),
];
const GENERAL: &[(f64, f64, f64)] = &[
    (4.0 / 3.0, -40.0, 136.81707876880793),
    (4.0 / 3.0, -5.0, 8.626787641214456),
    (4.0 / 3.0, -1.0, 1.2792792130800865),
    (4.0 / 3.0, 0.0, 0.41543046251477955),
    (4.0 / 3.0, 0.5, 0.19399311947423833),
    (4.0 / 3.0, 1.0, 0.07723960561831152),
    (4.0 / 3.0, 3.0, 0.00029456410601421085),
    (4.0 / 3.0, 6.0, 1.0023056032800434e-10),
    (1.25, -40.0, 100.60450009009871),
    (1.25, -5.0, 7.524136636509379),
    (1.25, -1.0, 1.2238769374739258),
    (1.25, 0.0, 0.40970482411012343),
    (1.25, 0.5, 0.1941217888174542),
    (1.25, 1.0, 0.07835825990143316),
    (1.25, 3.0, 0.0003126872688332529),
    (1.25, 6.0, 1.1137222195342809e-10),
    (1.056, -40.0, 49.17941731344133),
    (1.056, -5.0, 5.478175744377458),
    (1.056, -1.0, 1.1116659922977954),
    (1.056, 0.0, 0.400494089799183),
    (1.056, 0.5, 0.19651038863434087),
    (1.056, 1.0, 0.0819715581166761),
    (1.056, 3.0, 0.0003642782852357318),
    (1.056, 6.0, 1.4445579335556548e-10),
    (0.7, -40.0, 13.225542001697603),
    (0.7, -5.0, 3.0717790693777),
    (0.7, -1.0, 0.9591758938686605),
    (0.7, 0.0, 0.39999009534807295),
    (0.7, 0.5, 0.21025485817992476),
    (0.7, 1.0, 0.0935094966556834),
    (0.7, 3.0, 0.0005105696304697442),
    (0.7, 6.0, 2.4750242245450125e-10),
    (3.0, -40.0, 64120.0),
    (3.0, -5.0, 140.00000001020683),
    (3.0, -1.0, 4.091291157831602),
    (3.0, 0.0, 0.7978845608028654),
    (3.0, 0.5, 0.29077348478994514),
    (3.0, 1.0, 0.09129115783160184),
    (3.0, 3.0, 0.00015400339263467596),
    (3.0, 6.0, 2.2039354463483583e-11),
    (2.0, -40.0, 1601.0),
    (2.0, -5.0, 25.999999980656703),
    (2.0, -1.0, 1.9246602166562292),
    (2.0, 0.0, 0.5),
    (2.0, 0.5, 0.20963926002533387),
    (2.0, 1.0, 0.07533978334377076),
    (2.0, 3.0, 0.00020343508048692373),
    (2.0, 6.0, 4.8445767455118286e-11),
    (10.0, -40.0, 1.0783260551560946e+16),
    (10.0, -5.0, 39275319.999999985),
    (10.0, -1.0, 9481.88513750096),
    (10.0, 0.0, 472.5),
    (10.0, 0.5, 87.4759436835587),
    (10.0, 1.0, 14.114862499039978),
    (10.0, 3.0, 0.0020243823657402227),
    (10.0, 6.0, 1.471178357197337e-11),
];

/// Checks `value` against a number printed with a given number of digits:
/// the difference must be below half a unit of the last printed digit.
fn assert_printed(value: f64, printed: &str) {
    let (mantissa, exponent) = match printed.split_once('e') {
        Some((m, e)) => (m, e.parse::<i32>().unwrap()),
        None => (printed, 0),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
    let tolerance = 0.5 * 10f64.powi(exponent - decimals);
    let expected: f64 = printed.parse().unwrap();
    assert!(
        (value - expected).abs() <= tolerance,
        "{value:e} vs printed {printed} (tolerance {tolerance:e})"
    );
}

/// REFERENCE §3: F₀, F₁, F_{3/2} at h = −1..3, to every printed digit.
#[test]
fn reference_table_to_all_printed_digits() {
    let table = [
        (-1.0, "0.8413447461", "1.083315471", "1.40459747"),
        (0.0, "0.5", "0.3989422804", "0.4300199937"),
        (1.0, "0.1586552539", "0.08331547059", "0.07566817739"),
        (2.0, "0.02275013195", "0.008490702617", "0.006648177624"),
        (3.0, "0.001349898032", "0.000382154317", "0.0002639675543"),
    ];
    for (h, p0, p1, p32) in table {
        assert_printed(f0(h).unwrap(), p0);
        assert_printed(f1(h).unwrap(), p1);
        assert_printed(f3_2(h).unwrap(), p32);
    }
    // Exact values.
    assert_eq!(f0(0.0).unwrap(), 0.5);
    assert_relative_eq!(
        f1(0.0).unwrap(),
        1.0 / (2.0 * core::f64::consts::PI).sqrt(),
        max_relative = 1e-15
    );
}

/// REFERENCE §8: F₂(0) = 0.5, F_{5/2}(0) = 0.6166342, F_{3/2}(0.5) = 0.1952036,
/// F_{3/2}(1.5) = 2.463948e-2, F_{3/2}(4) = 4.439156e-6, and the closed form
/// F₂ = (1 + h²)Q − hφ.
#[test]
fn reference_section_8_values() {
    assert_relative_eq!(tail_moment(2.0, 0.0).unwrap(), 0.5, max_relative = 1e-12);
    assert_printed(f5_2(0.0).unwrap(), "0.6166342");
    assert_printed(tail_moment(2.5, 0.0).unwrap(), "0.6166342");
    assert_printed(f3_2(0.5).unwrap(), "0.1952036");
    assert_printed(f3_2(1.5).unwrap(), "2.463948e-2");
    assert_printed(f3_2(4.0).unwrap(), "4.439156e-6");
    for &h in &[-2.0, -0.3, 0.0, 0.8, 2.5] {
        let q = f0(h).unwrap();
        let phi = (-0.5 * h * h).exp() / (2.0 * core::f64::consts::PI).sqrt();
        assert_relative_eq!(
            tail_moment(2.0, h).unwrap(),
            (1.0 + h * h) * q - h * phi,
            max_relative = 1e-12
        );
    }
}

/// The speed-bar accuracy: F_{1/2}, F_{3/2}, F_{5/2} against the 40-digit
/// parabolic-cylinder values over h ∈ [−30, 37]; better than 1e-8 on
/// [−3, 6] by a wide margin (the library promises 1e-12 everywhere).
#[test]
fn half_integer_orders_match_parabolic_cylinder_reference() {
    let mut worst: f64 = 0.0;
    let mut worst_bar: f64 = 0.0;
    for &(h, r12, r32, r52) in HALF_INTEGER {
        for (value, reference) in [
            (f1_2(h).unwrap(), r12),
            (f3_2(h).unwrap(), r32),
            (f5_2(h).unwrap(), r52),
            (tail_moment(1.5, h).unwrap(), r32),
        ] {
            let e = (value / reference - 1.0).abs();
            assert!(
                e <= RELATIVE_ACCURACY,
                "h = {h}: {value:e} vs {reference:e} ({e:e})"
            );
            worst = worst.max(e);
            if (-3.0..=6.0).contains(&h) {
                worst_bar = worst_bar.max(e);
            }
        }
    }
    assert!(worst_bar <= 1e-8);
    eprintln!("half-integer orders: worst relative error {worst:.1e} ([-3, 6]: {worst_bar:.1e})");
}

/// Orders that are not half-integers (power-law asperities, (3-28)): the
/// tanh–sinh path and the moment series against the reference.
#[test]
fn general_orders_match_reference() {
    for &(q, h, reference) in GENERAL {
        let value = tail_moment(q, h).unwrap();
        assert!(
            (value / reference - 1.0).abs() <= 1e-11,
            "q = {q}, h = {h}: {value:e} vs {reference:e}"
        );
    }
}

/// Two independent methods on a dense grid over h ∈ [−3, 6]: the
/// trapezoidal fast path and the tanh–sinh quadrature (which also reports an
/// error estimate).
#[test]
fn trapezoid_agrees_with_tanh_sinh_on_a_dense_grid() {
    for i in 0..=900 {
        let h = -3.0 + 0.01 * i as f64;
        let fast = f3_2(h).unwrap();
        let quad = tail_moment_quadrature(1.5, h).unwrap();
        assert!(
            (fast / quad.value - 1.0).abs() <= 1e-11,
            "h = {h}: {fast:e} vs {:e}",
            quad.value
        );
        assert!(quad.error_estimate <= 1e-12 * quad.value, "{quad:?}");
        let fast = f1_2(h).unwrap();
        let quad = tail_moment_quadrature(0.5, h).unwrap();
        assert!((fast / quad.value - 1.0).abs() <= 1e-11, "h = {h}");
    }
}

/// Far tail: positive, finite, strictly decreasing up to h = 37 and
/// approaching `φ(h) Γ(5/2) h^{−5/2} (1 − 35/(8h²))`; beyond, underflow to
/// zero without NaN.
#[test]
fn far_tail_is_positive_monotone_and_asymptotic() {
    let mut previous = [f64::INFINITY; 4];
    for i in 0..=800 {
        let h = 0.05 * i as f64;
        let values = [
            f0(h).unwrap(),
            f1(h).unwrap(),
            f1_2(h).unwrap(),
            f3_2(h).unwrap(),
        ];
        for (k, &v) in values.iter().enumerate() {
            assert!(v.is_finite() && v >= 0.0, "h = {h}, k = {k}: {v}");
            if h <= 37.0 {
                assert!(
                    v > 0.0 && v < previous[k],
                    "h = {h}, k = {k}: {v} !< {}",
                    previous[k]
                );
            } else {
                // Subnormal range: no digits left to order, but no NaN,
                // no negative value and nothing above the scale of 1e-300.
                assert!(v <= 1e-300, "h = {h}, k = {k}");
            }
        }
        previous = values;
    }
    for &h in &[10.0f64, 15.0, 20.0, 30.0] {
        let phi = (-0.5 * h * h).exp() / (2.0 * core::f64::consts::PI).sqrt();
        let gamma_5_2 = 0.75 * core::f64::consts::PI.sqrt();
        let asymptotic = phi * gamma_5_2 * h.powf(-2.5) * (1.0 - 35.0 / (8.0 * h * h));
        let rel = (f3_2(h).unwrap() / asymptotic - 1.0).abs();
        // The next term of the series is 945/(32 h⁴)·(…) ≈ 30/h⁴.
        assert!(rel < 40.0 / h.powi(4), "h = {h}: {rel:e}");
    }
    assert_eq!(f3_2(60.0).unwrap(), 0.0);
}

/// Very negative h: F₀ → 1, F₁ = −h and the moment series
/// `F_{3/2} = |h|^{3/2}(1 + 3/(8h²) + 9/(128h⁴) + 0.1025390625/h⁶ + …)`,
/// `F_{1/2} = |h|^{1/2}(1 − 1/(8h²) − 15/(128h⁴) − 0.3076171875/h⁶ − …)`
/// (coefficients `C(q, 2k)(2k−1)!!`), continuous across the switch to the
/// series at −30.
#[test]
fn very_negative_h() {
    for &h in &[-29.0, -31.0, -100.0, -1e3, -1e6, -1e12] {
        let a = -h;
        let h2 = h * h;
        assert_eq!(f0(h).unwrap(), 1.0);
        assert_relative_eq!(f1(h).unwrap(), a, max_relative = 1e-15);
        let s32 = 1.0 + 3.0 / (8.0 * h2) + 9.0 / (128.0 * h2 * h2) + 0.1025390625 / h2.powi(3);
        assert_relative_eq!(f3_2(h).unwrap(), a.powf(1.5) * s32, max_relative = 1e-11);
        let s12 = 1.0 - 1.0 / (8.0 * h2) - 15.0 / (128.0 * h2 * h2) - 0.3076171875 / h2.powi(3);
        assert_relative_eq!(f1_2(h).unwrap(), a.sqrt() * s12, max_relative = 1e-11);
    }
    for q in [0.5, 1.5, 2.5, 1.25] {
        let below = tail_moment(q, -30.0).unwrap();
        let above = tail_moment(q, -30.0 + 1e-12).unwrap();
        assert_relative_eq!(below, above, max_relative = 1e-12);
    }
}

/// `dF_{3/2}/dh = −(3/2) F_{1/2}` and `dF₁/dh = −F₀` (central differences).
#[test]
fn derivative_identities() {
    for &h in &[-5.0, -1.0, 0.0, 0.7, 2.0, 4.0] {
        let e = 1e-5;
        let d32 = (f3_2(h + e).unwrap() - f3_2(h - e).unwrap()) / (2.0 * e);
        assert_relative_eq!(d32, -1.5 * f1_2(h).unwrap(), max_relative = 1e-7);
        let d1 = (f1(h + e).unwrap() - f1(h - e).unwrap()) / (2.0 * e);
        assert_relative_eq!(d1, -f0(h).unwrap(), max_relative = 1e-7);
    }
}

#[test]
fn invalid_arguments_are_named() {
    for h in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for r in [f0(h), f1(h), f1_2(h), f3_2(h), f5_2(h), tail_moment(1.2, h)] {
            assert!(
                matches!(r, Err(Error::InvalidArgument { name: "h", .. })),
                "{r:?}"
            );
        }
    }
    for q in [-0.1, 16.5, f64::NAN] {
        assert!(matches!(
            tail_moment(q, 0.0),
            Err(Error::InvalidArgument { name: "q", .. })
        ));
    }
}

/// Fuzzing regression (fuzz/regressions/c_abi/gw_tiny_sigma_slow): far above
/// the summits (h = d/σ huge: σ = 2.2e-308 m) the Gaussian tail moments are
/// 0 in f64 and come back at once; before, h² overflowed and the trapezoidal
/// sum ran 2³² terms (150 s per call). Continuous across the switch at
/// h = 40: the moments have underflowed well before it.
#[test]
fn tail_moments_far_above_the_summits_are_zero_and_fast() {
    use asperity::statistics::gaussian::{f1_2, f3_2, f5_2, tail_moment};
    let start = std::time::Instant::now();
    for h in [39.0, 40.0, 1e10, 1e154, 1e200, 1.5e291, f64::MAX] {
        assert_eq!(f1_2(h).unwrap(), 0.0, "F_1/2({h:e})");
        assert_eq!(f3_2(h).unwrap(), 0.0, "F_3/2({h:e})");
        assert_eq!(f5_2(h).unwrap(), 0.0, "F_5/2({h:e})");
        assert_eq!(tail_moment(2.3, h).unwrap(), 0.0, "F_2.3({h:e})");
    }
    // Below the switch the moments are still positive.
    assert!(f3_2(30.0).unwrap() > 0.0 && tail_moment(2.3, 30.0).unwrap() > 0.0);
    assert!(
        start.elapsed().as_secs_f64() < 5.0,
        "took {:?}",
        start.elapsed()
    );
}
