//! Surface profiles and maps: readers, form removal and filtering, ISO 4287
//! parameters, autocorrelation and power spectral density, generators and the
//! representative elementary pattern (thesis sections 1.5, 1.7).
