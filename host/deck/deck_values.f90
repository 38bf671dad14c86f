!> The values that Abaqus knows for the enumerated parameters the reader reads, so that an abbreviated value is
!> taken for the one value it begins (Abaqus Analysis User's Guide, "Input syntax rules": keywords, parameters and,
!> in most cases, parameter values need not be spelled out completely, as long as enough characters distinguish
!> them from the others that begin in the same way: *STEP, AMPLITUDE=RAM is AMPLITUDE=RAMP). Each list holds every
!> value the Abaqus Keywords Guide gives the parameter (not only those ldfcz supports), so that uniqueness is
!> judged as Abaqus judges it; a value that begins several of them is left as written (and refused by the reader).
module deck_values
  implicit none
  private
  public :: abaqus_values, expand_value, no_blanks

contains

  !> '|'-separated values of parameter param of keyword kw (both upper case, normalised); '' when the parameter is
  !> not an enumeration the reader reads (a name, a number, or a flag).
  pure function abaqus_values(kw, param) result(list)
    character(len=*), intent(in) :: kw     !< keyword, e.g. '*STEP'
    character(len=*), intent(in) :: param  !< parameter, e.g. 'AMPLITUDE'
    character(len=:), allocatable :: list
    list = ''
    select case (param)
    case ('OP')
      select case (kw)
      case ('*BOUNDARY', '*CLOAD', '*DLOAD', '*DSLOAD', '*TEMPERATURE', '*FIELD')
        list = 'MOD|NEW'
      case ('*OUTPUT')
        list = 'ADD|NEW|REPLACE'
      end select
    case ('NLGEOM', 'UNSYMM', 'ADJUST', 'SUMMARY', 'GLOBAL')
      if (any(kw == [character(len=16) :: '*STEP', '*TIE', '*NODE PRINT', '*EL PRINT'])) list = 'YES|NO'
    case ('TOTALS')
      if (kw == '*NODE PRINT' .or. kw == '*EL PRINT') list = 'YES|NO|ONLY'
    case ('AMPLITUDE')
      if (kw == '*STEP') list = 'RAMP|STEP'
    case ('EXTRAPOLATION')
      if (kw == '*STEP') list = 'LINEAR|PARABOLIC|VELOCITY PARABOLIC|NO'
    case ('DEFINITION')
      if (kw == '*AMPLITUDE') list = 'TABULAR|EQUALLY SPACED|PERIODIC|MODULATED|DECAY|SMOOTH STEP|'// &
        'SOLUTION DEPENDENT|BUBBLE|USER|ACTUATOR|SPECTRUM|PSD'
      if (kw == '*ORIENTATION') list = 'COORDINATES|NODES|OFFSET TO NODES'
    case ('TIME')
      if (kw == '*AMPLITUDE') list = 'STEP TIME|TOTAL TIME'
    case ('VALUE')
      if (kw == '*AMPLITUDE') list = 'RELATIVE|ABSOLUTE'
    case ('SYSTEM')
      if (kw == '*ORIENTATION') list = 'RECTANGULAR|CYLINDRICAL|SPHERICAL|Z RECTANGULAR|USER'
      if (kw == '*NODE') list = 'R|C|S'
    case ('POSITION')
      if (kw == '*EL PRINT') list = 'INTEGRATION POINTS|CENTROIDAL|NODES|AVERAGED AT NODES'
    case ('VARIABLE')
      if (any(kw == [character(len=16) :: '*OUTPUT', '*NODE OUTPUT', '*ELEMENT OUTPUT'])) list = 'PRESELECT|ALL'
    case ('FIELD')
      if (kw == '*CONTROLS') list = 'GLOBAL|DISPLACEMENT|HYDROSTATIC FLUID PRESSURE|ROTATION|TEMPERATURE|'// &
        'PORE FLUID PRESSURE|ELECTRICAL POTENTIAL|CONCENTRATION|CONSTRAINT|ELECTRICAL FLUX'
    case ('PARAMETERS')
      if (kw == '*CONTROLS') list = 'FIELD|TIME INCREMENTATION|LINE SEARCH|CONSTRAINTS|FLOW|STABILIZATION|'// &
        'VELOCITY'
    case ('HOURGLASS')
      if (kw == '*SECTION CONTROLS') list = 'ENHANCED|RELAX STIFFNESS|STIFFNESS|VISCOUS|COMBINED'
    case ('ELEMENT DELETION')
      if (kw == '*SECTION CONTROLS') list = 'YES|NO'
    case ('TYPE')
      list = type_values(kw)
    end select
  end function abaqus_values

  !> The values of TYPE= of keyword kw ('' when not an enumeration read here).
  pure function type_values(kw) result(list)
    character(len=*), intent(in) :: kw  !< keyword
    character(len=:), allocatable :: list
    select case (kw)
    case ('*ELASTIC')
      list = 'ISOTROPIC|ORTHOTROPIC|ENGINEERING CONSTANTS|LAMINA|ANISOTROPIC|TRACTION|COUPLED TRACTION|'// &
        'BILAMINA|SHEAR|SHORT FIBER'
    case ('*EXPANSION')
      list = 'ISO|ORTHO|ANISO|SHORT FIBER'
    case ('*USER MATERIAL')
      list = 'MECHANICAL|THERMAL|BOTH'
    case ('*BOUNDARY')
      list = 'DISPLACEMENT|VELOCITY|ACCELERATION'
    case ('*TIE')
      list = 'SURFACE TO SURFACE|NODE TO SURFACE'
    case ('*TRANSFORM')
      list = 'R|C|S'
    case ('*SURFACE')
      list = 'ELEMENT|NODE|SEGMENTS|CYLINDER|REVOLUTION|CUTTING SURFACE|EULERIAN MATERIAL|USER'
    case ('*INITIAL CONDITIONS')
      list = 'ACOUSTIC STATIC PRESSURE|ACTIVATION|CONCENTRATION|CONTACT|CURE|DAMAGE INITIATION|ENRICHMENT|'// &
        'FIELD|FLUID PRESSURE|HARDENING|INITIAL GAP|INTERFACE|IONIC CONCENTRATION|MASS FLOW RATE|NODE REF '// &
        'COORDINATE|NORMAL|PLASTIC STRAIN|PORE PRESSURE|PRESSURE STRESS|RATIO|REF COORDINATE|REFERENCE STRESS|'// &
        'RELATIVE DENSITY|ROTATING VELOCITY|SATURATION|SOLUTION|SPECIFIC ENERGY|SPUD CAN|STRESS|TEMPERATURE|'// &
        'VELOCITY|VOID RATIO|VOLUME FRACTION|EFFECTIVE STRAIN'
    case default
      list = ''
    end select
  end function type_values

  !> The value v (normalised) expanded to the one value of list it abbreviates; v itself when it is a value of the
  !> list, abbreviates none or several of them, or the list is empty.
  pure function expand_value(v, list) result(full)
    character(len=*), intent(in) :: v     !< value as given (upper case, normalised)
    character(len=*), intent(in) :: list  !< '|'-separated values
    character(len=:), allocatable :: full
    integer :: i, j, n
    character(len=:), allocatable :: cand, sc, sv
    full = v
    if (len(v) == 0 .or. len(list) == 0) return
    sv = no_blanks(v)
    n = 0
    i = 1
    do while (i <= len(list))
      j = index(list(i:), '|')
      if (j == 0) then
        cand = list(i:)
        i = len(list) + 1
      else
        cand = list(i:i + j - 2)
        i = i + j
      end if
      ! blanks on a keyword line are ignored: compared without them (SMOOTHSTEP is SMOOTH STEP)
      sc = no_blanks(cand)
      if (sc == sv) then
        full = cand
        return
      end if
      if (len(sv) < len(sc)) then
        if (sc(1:len(sv)) == sv) then
          n = n + 1
          if (n == 1) full = cand
        end if
      end if
    end do
    if (n /= 1) full = v
  end function expand_value

  !> Text without its blanks (Abaqus ignores blanks on keyword lines: *SOLIDSECTION is *SOLID SECTION).
  pure function no_blanks(s) result(t)
    character(len=*), intent(in) :: s  !< text
    character(len=:), allocatable :: t
    integer :: i
    t = ''
    do i = 1, len(s)
      if (s(i:i) /= ' ') t = t//s(i:i)
    end do
  end function no_blanks

end module deck_values
