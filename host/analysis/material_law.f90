!> The elastic law of a model material for the continuum elements: the deck's *ELASTIC and *EXPANSION tables
!> (model_types) as solid_elastic's elastic_law_t, checked at set-up so that a bad law is a deck error naming the
!> *ELASTIC line. A constant isotropic law with a constant isotropic expansion stays the element's e, nu, alpha
!> (law%general = .false.), so those materials compute exactly as before.
module material_law
  use ldfcz_kinds, only: dp
  use model_types, only: material_t
  use deck_lists, only: itoa
  use solid_elastic, only: elastic_law_t, elastic_law_check, law_isotropic, expansion_none
  implicit none
  private
  public :: material_elastic_law

contains

  !> The law of material mt (stat = 2 and errmsg "file:line: *ELASTIC: ..." when its constants give no positive
  !> definite stiffness at a data point).
  subroutine material_elastic_law(mt, law, stat, errmsg)
    type(material_t), intent(in) :: mt                   !< the material
    type(elastic_law_t), intent(out) :: law              !< its law
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    character(len=200) :: why
    logical :: general
    stat = 0
    errmsg = ''
    general = .false.
    if (mt%has_elastic) general = mt%elastic_kind /= law_isotropic .or. size(mt%elastic_temp) > 1
    if (mt%has_expansion) general = general .or. mt%expansion_kind /= 1 .or. size(mt%expansion_temp) > 1
    if (.not. general) return
    law%general = .true.
    if (mt%has_elastic) then
      law%kind = mt%elastic_kind
      law%temp = mt%elastic_temp
      law%data = mt%elastic_data
    else
      ! a UMAT material: only the expansion is used
      law%kind = law_isotropic
      allocate (law%temp(1), law%data(2, 1))
      law%temp = 0.0_dp
      law%data(:, 1) = [1.0_dp, 0.0_dp]
    end if
    law%exp_kind = expansion_none
    if (mt%has_expansion) then
      law%exp_kind = mt%expansion_kind
      law%exp_temp = mt%expansion_temp
      law%exp_data = mt%expansion_data
      law%zero = mt%expansion_zero
    end if
    if (.not. mt%has_elastic) return
    call elastic_law_check(law, stat, why)
    if (stat /= 0) then
      stat = 2
      errmsg = mt%elastic_pos%file//':'//itoa(mt%elastic_pos%line)//': '//trim(why)//' (material '// &
        trim(mt%given_name)//')'
    end if
  end subroutine material_elastic_law

end module material_law
