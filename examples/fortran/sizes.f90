!> The size of every `type, bind(c)` mirror of the Fortran module
!> (`c_sizeof`) next to the size the library reports for the C type
!> (`asperity_type_layout`), and every type the library lists checked to
!> have a mirror here.
!>
!> Rows "size <C name> <c_sizeof> <library size> <library alignment>" and
!> lines "CHECK <name> <value>" are read by tests/fortran_bindings.rs, which
!> also checks that every struct of include/asperity.h has a row.
program sizes
  use asperity
  use, intrinsic :: iso_c_binding, only: c_sizeof
  implicit none
  integer, parameter :: max_types = 128
  character(len=64) :: seen(max_types)
  integer :: n_seen = 0, mismatches = 0, missing = 0
  integer(c_size_t) :: i
  character(len=:), allocatable :: name
  logical :: found
  integer :: k, state_size
  type(asperity_homogenised_friction) :: table
  type(asperity_friction) :: law
  type(asperity_hertz_params) :: hertz
  type(asperity_power_punch_params) :: power_punch
  type(asperity_flat_punch_params) :: flat_punch
  type(asperity_dmt_params) :: dmt
  type(asperity_jkr_params) :: jkr
  type(asperity_jkr_power_punch_params) :: jkr_power_punch
  type(asperity_kendall_params) :: kendall
  type(asperity_maugis_dugdale_params) :: maugis_dugdale
  type(asperity_derjaguin_params) :: derjaguin
  type(asperity_law_params) :: law_params
  type(asperity_normal_law) :: normal_law
  type(asperity_contact_state) :: contact_state
  type(asperity_normal_response) :: normal_response
  type(asperity_fidelity_assessment) :: fidelity_assessment
  type(asperity_fidelity_advice) :: fidelity_advice
  type(asperity_nano_asperities) :: nano_asperities
  type(asperity_dissipation) :: dissipation
  type(asperity_homogenised_sample) :: homogenised_sample
  type(asperity_friction_increment) :: friction_increment
  type(asperity_friction_response) :: friction_response
  type(asperity_indentation_options) :: indentation_options
  type(asperity_indentation_result) :: indentation_result
  type(asperity_afm_fit) :: afm_fit
  type(asperity_afm_result) :: afm_result
  type(asperity_slider_info) :: slider_info
  type(asperity_slider_record) :: slider_record
  type(asperity_slider_options) :: slider_options
  type(asperity_lugre_params) :: lugre_params
  type(asperity_generalized_maxwell_slip_params) :: gms_params
  type(asperity_cantor_profile) :: cantor_profile
  type(asperity_cantor_contact) :: cantor_contact
  type(asperity_prandtl_tomlinson_two_spring_params) :: two_spring_params
  type(asperity_burridge_knopoff_params) :: burridge_knopoff_params
  type(asperity_friction_material) :: friction_material
  type(asperity_gw_params) :: gw_params
  type(asperity_gw_response) :: gw_response
  type(asperity_separation) :: separation
  type(asperity_bgt_params) :: bgt_params
  type(asperity_bgt_response) :: bgt_response
  type(asperity_bora_response) :: bora_response
  type(asperity_sergienko_bukharov_params) :: sb_params
  type(asperity_sergienko_bukharov_result) :: sb_result
  type(asperity_zhuravlev) :: zhuravlev
  type(asperity_zhuravlev_response) :: zhuravlev_response
  type(asperity_zhuravlev_friction) :: zhuravlev_friction
  type(asperity_roughness) :: roughness
  type(asperity_hurst_fit) :: hurst_fit
  type(asperity_peak_statistics) :: peak_statistics
  type(asperity_borodich_kryukova) :: borodich_kryukova
  type(asperity_borodich_kryukova_state) :: borodich_kryukova_state
  type(asperity_borodich_kryukova_sample) :: borodich_kryukova_sample
  type(asperity_schmittbuhl) :: schmittbuhl
  type(asperity_schmittbuhl_generation) :: schmittbuhl_generation
  type(asperity_hurst_estimate) :: hurst_estimate

  call row('AsperityHertzParams', c_sizeof(hertz))
  call row('AsperityPowerPunchParams', c_sizeof(power_punch))
  call row('AsperityFlatPunchParams', c_sizeof(flat_punch))
  call row('AsperityDmtParams', c_sizeof(dmt))
  call row('AsperityJkrParams', c_sizeof(jkr))
  call row('AsperityJkrPowerPunchParams', c_sizeof(jkr_power_punch))
  call row('AsperityKendallParams', c_sizeof(kendall))
  call row('AsperityMaugisDugdaleParams', c_sizeof(maugis_dugdale))
  call row('AsperityDerjaguinParams', c_sizeof(derjaguin))
  call row('AsperityLawParams', c_sizeof(law_params))
  call row('AsperityNormalLaw', c_sizeof(normal_law))
  call row('AsperityContactState', c_sizeof(contact_state))
  call row('AsperityNormalResponse', c_sizeof(normal_response))
  call row('AsperityFidelityAssessment', c_sizeof(fidelity_assessment))
  call row('AsperityFidelityAdvice', c_sizeof(fidelity_advice))
  call row('AsperityNanoAsperities', c_sizeof(nano_asperities))
  call row('AsperityDissipation', c_sizeof(dissipation))
  call row('AsperityHomogenisedSample', c_sizeof(homogenised_sample))
  call row('AsperityFrictionIncrement', c_sizeof(friction_increment))
  call row('AsperityFrictionResponse', c_sizeof(friction_response))
  call row('AsperityIndentationOptions', c_sizeof(indentation_options))
  call row('AsperityIndentationResult', c_sizeof(indentation_result))
  call row('AsperityAfmFit', c_sizeof(afm_fit))
  call row('AsperityAfmResult', c_sizeof(afm_result))
  call row('AsperitySliderInfo', c_sizeof(slider_info))
  call row('AsperitySliderRecord', c_sizeof(slider_record))
  call row('AsperitySliderOptions', c_sizeof(slider_options))
  call row('AsperityLugreParams', c_sizeof(lugre_params))
  call row('AsperityGeneralizedMaxwellSlipParams', c_sizeof(gms_params))
  call row('AsperityCantorProfile', c_sizeof(cantor_profile))
  call row('AsperityCantorContact', c_sizeof(cantor_contact))
  call row('AsperityPrandtlTomlinsonTwoSpringParams', c_sizeof(two_spring_params))
  call row('AsperityBurridgeKnopoffParams', c_sizeof(burridge_knopoff_params))
  call row('AsperityFrictionMaterial', c_sizeof(friction_material))
  call row('AsperityGwParams', c_sizeof(gw_params))
  call row('AsperityGwResponse', c_sizeof(gw_response))
  call row('AsperitySeparation', c_sizeof(separation))
  call row('AsperityBgtParams', c_sizeof(bgt_params))
  call row('AsperityBgtResponse', c_sizeof(bgt_response))
  call row('AsperityBoraResponse', c_sizeof(bora_response))
  call row('AsperitySergienkoBukharovParams', c_sizeof(sb_params))
  call row('AsperitySergienkoBukharovResult', c_sizeof(sb_result))
  call row('AsperityZhuravlev', c_sizeof(zhuravlev))
  call row('AsperityZhuravlevResponse', c_sizeof(zhuravlev_response))
  call row('AsperityZhuravlevFriction', c_sizeof(zhuravlev_friction))
  call row('AsperityRoughness', c_sizeof(roughness))
  call row('AsperityHurstFit', c_sizeof(hurst_fit))
  call row('AsperityPeakStatistics', c_sizeof(peak_statistics))
  call row('AsperityBorodichKryukova', c_sizeof(borodich_kryukova))
  call row('AsperityBorodichKryukovaState', c_sizeof(borodich_kryukova_state))
  call row('AsperityBorodichKryukovaSample', c_sizeof(borodich_kryukova_sample))
  call row('AsperitySchmittbuhl', c_sizeof(schmittbuhl))
  call row('AsperitySchmittbuhlGeneration', c_sizeof(schmittbuhl_generation))
  call row('AsperityHurstEstimate', c_sizeof(hurst_estimate))

  ! Every type the library knows has a row above.
  do i = 0, asperity_type_count() - 1
    call asperity_type_name(i, name)
    found = .false.
    do k = 1, n_seen
      if (seen(k) == name) found = .true.
    end do
    if (.not. found) then
      write (*, '(a)') 'no Fortran mirror for '//name
      missing = missing + 1
    end if
  end do

  call check('mirrors', real(n_seen, c_double))
  call check('library_types', real(asperity_type_count(), c_double))
  call check('mismatches', real(mismatches, c_double))
  call check('library_types_without_mirror', real(missing, c_double))
  ! A friction state is an array of doubles: the homogenised law's holds the
  ! common accumulators, the stick force, the plastic slip path and the four
  ! mechanisms, as the header's indices say.
  homogenised_sample%pressure = 1e6_c_double
  homogenised_sample%cof = 0.5_c_double
  homogenised_sample%contact_fraction = 0.01_c_double
  homogenised_sample%shares%chemical = 1
  call asperity_homogenised_friction_new([homogenised_sample], table)
  call asperity_friction_from_homogenised(table, 0.0_c_double, law)
  call asperity_friction_state_size(law, state_size)
  call check('state_size_matches', merge(1.0_c_double, 0.0_c_double, &
      state_size == ASPERITY_HOMOGENISED_STATE_MECHANISMS + 4))
  call law%free()
  call table%free()
  ! Released so leak checkers (scripts/memcheck.sh) see a clean exit.
  if (allocated(name)) deallocate (name)

contains

  subroutine row(c_name, fortran_size)
    character(len=*), intent(in) :: c_name
    integer(c_size_t), intent(in) :: fortran_size
    integer(c_size_t) :: size, align
    integer(c_int32_t) :: st
    call asperity_type_layout(c_name, size, align, status=st)
    if (st /= ASPERITY_OK) then
      write (*, '(a)') 'asperity_type_layout('//c_name//') failed: '// &
          asperity_last_error_message()
      size = 0
      align = 0
    end if
    write (*, '(a, 1x, a, 3(1x, i0))') 'size', c_name, fortran_size, size, align
    if (size /= fortran_size) mismatches = mismatches + 1
    n_seen = n_seen + 1
    seen(n_seen) = c_name
  end subroutine row

  subroutine check(what, value)
    character(len=*), intent(in) :: what
    real(c_double), intent(in) :: value
    character(len=32) :: buf
    write (buf, '(es25.17e3)') value
    write (*, '(a)') 'CHECK '//what//' '//trim(adjustl(buf))
  end subroutine check

end program sizes
