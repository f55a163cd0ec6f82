//! Statistical multi-asperity models: Zhuravlev, Greenwood–Williamson,
//! Kragelsky's rod assembly and the power-law asperity extensions through
//! rescaling (thesis sections 1.6, 3.4, 5.3–5.4).
