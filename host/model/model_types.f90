!> Model data of an ldfcz analysis, as read from an Abaqus-style deck: nodes, elements, sets, sections,
!> materials, user element types, amplitudes and steps. Pure data; the deck reader fills it, the analysis reads it.
module model_types
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: model_t, node_set_t, elem_set_t, material_t, section_t, user_element_type_t, amplitude_t
  public :: uel_property_t, boundary_t, node_print_t, step_t, source_pos_t, cload_t, dload_t, surface_t
  public :: dload_bx, dload_grav, dload_pressure, dload_user, dload_centrif, dload_rota, model_find_surface
  public :: coupling_t, pretension_t, model_change_t, time_points_t, model_dof, model_dof_node, model_find_time_points
  public :: initial_condition_t, init_stress, init_solution, equation_t, tie_t
  public :: etype_user, name_len, max_node_dof
  public :: model_find_nset, model_find_elset, model_find_material, model_find_amplitude, model_find_user_type
  public :: model_find_orientation
  public :: amplitude_value, amplitude_factor, transform_t
  public :: instance_t, model_label_text, el_print_t, orientation_t, orientation_axes, output_request_t, model_sdv_name
  public :: elastic_lamina, model_elements_leave

  integer, parameter :: name_len = 80      !< longest name kept (set, material, type names)
  !> model_t%elem_kind of a user element (UEL); a continuum element's kind is its index in the element catalogue
  !> (element_catalog.f90: element_types), which holds everything about the continuum types
  integer, parameter :: etype_user = 0
  integer, parameter :: elastic_lamina = 4  !< *ELASTIC, TYPE=LAMINA in material_t%elastic_kind (solid_elastic's law_lamina)
  integer, parameter :: max_node_dof = 3   !< displacement dofs per node at most
  integer, parameter :: init_stress = 1    !< *INITIAL CONDITIONS, TYPE=STRESS
  integer, parameter :: init_solution = 2  !< *INITIAL CONDITIONS, TYPE=SOLUTION
  integer, parameter :: dload_bx = 1       !< body force per unit reference volume along dir (BX, BY, BZ)
  integer, parameter :: dload_grav = 2     !< gravity: density x magnitude along dir (GRAV)
  integer, parameter :: dload_pressure = 3 !< face pressure Pn (follower under NLGEOM)
  integer, parameter :: dload_user = 4     !< user element load type Un (passed to the UEL)
  integer, parameter :: dload_centrif = 5  !< CENTRIF: rho omega^2 (x - p)_perp about an axis (magnitude omega^2)
  integer, parameter :: dload_rota = 6     !< ROTA: the d'Alembert force -rho alpha n x (x - p) (magnitude alpha)

  !> Where an item came from in the deck (for error messages found after reading).
  type :: source_pos_t
    character(len=:), allocatable :: file  !< file name
    integer :: line = 0                    !< line number in that file
    character(len=name_len) :: keyword = ''!< keyword of the block
  end type source_pos_t

  type :: node_set_t
    character(len=name_len) :: name = ''   !< upper-case name
    integer, allocatable :: nodes(:)       !< node indices (1..nnode) in the model arrays
    integer :: n = 0                       !< members in use while reading (size(nodes) afterwards)
    logical :: unsorted = .false.          !< UNSORTED: the members' order as given matters (*EQUATION pairs)
  end type node_set_t

  type :: elem_set_t
    character(len=name_len) :: name = ''   !< upper-case name
    integer, allocatable :: elems(:)       !< element indices (1..nelem)
    integer :: n = 0                       !< members in use while reading (size(elems) afterwards)
  end type elem_set_t

  type :: material_t
    character(len=name_len) :: name = ''   !< upper-case name
    character(len=name_len) :: given_name = '' !< name as written in the deck (passed to UMAT as CMNAME)
    logical :: has_elastic = .false.       !< *ELASTIC given
    real(dp) :: young = 0.0_dp             !< Young's modulus [MPa]
    real(dp) :: poisson = 0.0_dp           !< Poisson ratio [-]
    logical :: has_user = .false.          !< *USER MATERIAL given
    real(dp), allocatable :: props(:)      !< user material constants
    logical :: unsymm = .false.            !< *USER MATERIAL, UNSYMM
    integer :: nstatv = 0                  !< *DEPVAR
    character(len=name_len), allocatable :: sdv_key(:)  !< *DEPVAR output key of each state variable ('' none)
    character(len=name_len), allocatable :: sdv_desc(:) !< *DEPVAR description of each ('' none)
    integer :: delete_sdv = 0              !< *DEPVAR, DELETE=: the state variable whose 0 deletes the point (0: none)
    type(source_pos_t) :: delete_pos       !< the *DEPVAR line (messages about DELETE=)
    integer :: plastic_statev = 0          !< STATEV of an equivalent plastic strain, '**LDFCZ STATEV' (0: none)
    logical :: has_expansion = .false.     !< *EXPANSION given
    real(dp) :: alpha = 0.0_dp             !< isotropic thermal expansion coefficient [1/K]
    ! *ELASTIC and *EXPANSION as tables over temperature (docs/host.md); young, poisson and alpha above hold the
    ! constant isotropic case, which these tables then also describe (one data point)
    integer :: elastic_kind = 0            !< 0 none, 1 ISOTROPIC, 2 ORTHOTROPIC, 3 ENGINEERING CONSTANTS, 4 LAMINA,
                                           !< 5 ANISOTROPIC (solid_elastic's law_*)
    real(dp), allocatable :: elastic_temp(:)     !< (npoint) temperatures of the data points, ascending
    real(dp), allocatable :: elastic_data(:, :)  !< (constants, npoint) as the Keywords Guide orders them
    type(source_pos_t) :: elastic_pos      !< the *ELASTIC line
    integer :: expansion_kind = 0          !< 0 none, 1 ISO, 2 ORTHO, 3 ANISO
    real(dp), allocatable :: expansion_temp(:)    !< (npoint) temperatures, ascending
    real(dp), allocatable :: expansion_data(:, :) !< (1, 3 or 6, npoint) coefficients
    real(dp) :: expansion_zero = 0.0_dp    !< ZERO=: reference temperature of the coefficients
    logical :: has_density = .false.      !< *DENSITY given
    real(dp) :: density = 0.0_dp           !< mass density [t/mm^3 in N, mm, s units]
    logical :: density_varies = .false.    !< *DENSITY given at several temperatures (refused with GRAV)
    type(source_pos_t) :: pos              !< where *MATERIAL was
    type(source_pos_t) :: user_pos         !< first data line of *USER MATERIAL (messages of a UMAT's XIT)
    character(len=name_len) :: builtin = '' !< '**LDFCZ BUILTIN, UMAT=name': the built-in UMAT it may run ('' none)
    type(source_pos_t) :: builtin_pos      !< where that declaration is
  end type material_t

  type :: section_t
    character(len=name_len) :: elset = ''  !< element set
    character(len=name_len) :: material = '' !< material name
    real(dp) :: thickness = 1.0_dp         !< plane-strain thickness [mm]
    type(source_pos_t) :: pos
    character(len=name_len) :: orientation = '' !< ORIENTATION= ('' none)
    integer :: iorient = 0                 !< its index in model%orientations (finish_model)
  end type section_t

  !> *ORIENTATION: local material axes (docs/host.md). Points in model coordinates (an instance's placement applied).
  type :: orientation_t
    character(len=name_len) :: name = ''   !< upper-case name
    integer :: system = 1                  !< 1 RECTANGULAR, 2 CYLINDRICAL, 3 SPHERICAL (*TRANSFORM, TYPE=S only)
    logical :: by_nodes = .false.          !< DEFINITION=NODES: a, b, c are nodes (nodes(:), model labels)
    real(dp) :: a(3) = 0.0_dp              !< RECTANGULAR: point on local 1; CYLINDRICAL: first point on the axis
    real(dp) :: b(3) = 0.0_dp              !< RECTANGULAR: point in the 1-2 plane; CYLINDRICAL: second axis point
    real(dp) :: c(3) = 0.0_dp              !< RECTANGULAR: origin
    integer :: nodes(3) = 0                !< DEFINITION=NODES: labels of a, b, c (0: c at the global origin)
    integer :: extra_axis = 0              !< additional rotation about local axis 1..3 (0: none)
    real(dp) :: extra_angle = 0.0_dp       !< its angle [degrees]
    type(source_pos_t) :: pos
  end type orientation_t

  !> A *TRANSFORM: the local node system (axes from orientation_axes at the node's reference position) of the nodes
  !> of a node set. TYPE=R: system 1 with c = the origin; TYPE=C: system 2; TYPE=S: system 3.
  type :: transform_t
    type(orientation_t) :: axes            !< the system (a, b, c; no additional rotation)
    integer :: nset = 0                    !< node set index
    character(len=1) :: kind = 'R'         !< TYPE= as given (R, C, S)
    type(source_pos_t) :: pos
  end type transform_t

  type :: user_element_type_t
    character(len=name_len) :: name = ''   !< e.g. U1
    integer :: jtype = 0                   !< the number n of type Un
    integer :: nnode = 0                   !< NODES
    integer :: mcrd = 0                    !< COORDINATES
    integer :: nprops = 0                  !< PROPERTIES
    integer :: njprops = 0                 !< I PROPERTIES
    integer :: nsvars = 0                  !< VARIABLES
    logical :: unsymm = .false.            !< UNSYMM
    integer, allocatable :: active(:)      !< active dofs per node (1..3)
    ! the SVARS layout declared by '**LDFCZ SVARS' (docs/uel.md, "Declaring the SVARS layout"); 0 = not declared
    integer :: sv_points = 0               !< integration points (SVARS point-major)
    integer :: sv_per_point = 0            !< SVARS entries per point
    integer :: sv_delta_max = 0            !< position in a point's block: largest opening so far
    integer :: sv_opening = 0              !< position: opening magnitude
    integer :: sv_traction = 0             !< position: traction magnitude
    integer :: sv_length_prop = 0          !< PROPS entry of the opening length scale (delta)
    type(source_pos_t) :: pos
    character(len=name_len) :: builtin = '' !< '**LDFCZ BUILTIN, UEL=name': the built-in UEL it may run ('' none)
    type(source_pos_t) :: builtin_pos      !< where that declaration is
  end type user_element_type_t

  !> One *UEL PROPERTY block.
  type :: uel_property_t
    real(dp), allocatable :: props(:)      !< NPROPS real properties
    integer, allocatable :: jprops(:)      !< NJPROP integer properties
    type(source_pos_t) :: pos              !< first data line of the block (messages of a UEL's XIT)
  end type uel_property_t

  type :: amplitude_t
    character(len=name_len) :: name = ''
    real(dp), allocatable :: t(:)          !< times (step time)
    real(dp), allocatable :: a(:)          !< amplitude values
    logical :: smooth = .false.            !< DEFINITION=SMOOTH STEP (else TABULAR: piecewise linear)
    logical :: total_time = .false.        !< TIME=TOTAL TIME (else step time)
  end type amplitude_t

  !> One prescribed dof range on a set of nodes.
  type :: boundary_t
    integer, allocatable :: nodes(:)       !< node indices
    integer :: first_dof = 0               !< first dof (1..6; 4..6 rotations of a coupling's reference node)
    integer :: last_dof = 0                !< last dof (1..6)
    !> the rotations a type sets besides first_dof..last_dof (ENCASTRE 4, 5, 6; XSYMM 5, 6; ...; 0: none), applied
    !> where a node has them (a coupling's reference node) and dropped elsewhere
    integer :: rot_dofs(3) = 0
    real(dp) :: value = 0.0_dp             !< magnitude
    integer :: amplitude = 0               !< amplitude index, 0 = default (ramp in a static step)
    logical :: velocity = .false.          !< TYPE=VELOCITY: value is a velocity (increment = v dt)
    logical :: user = .false.              !< USER: the value is what the user subroutine DISP returns
    logical :: fixed = .false.             !< FIXED: held at the value the dof has at the start of the step
    type(source_pos_t) :: pos
  end type boundary_t

  !> One *CLOAD data line: a fixed-direction nodal force on one dof of a set of nodes.
  type :: cload_t
    integer, allocatable :: nodes(:)       !< node indices
    integer :: dof = 0                     !< dof (1..3)
    real(dp) :: value = 0.0_dp             !< magnitude [N]
    integer :: amplitude = 0               !< amplitude index, 0 = the step's default (RAMP or STEP)
    type(source_pos_t) :: pos
  end type cload_t

  !> One distributed load definition (*DLOAD or *DSLOAD data line) on a list of elements.
  type :: dload_t
    integer, allocatable :: elems(:)       !< element indices (user ids, negative, until finish_model)
    integer, allocatable :: faces(:)       !< per element: face 1..6 (pressure), else 0
    integer :: kind = 0                    !< dload_bx, dload_grav, dload_pressure, dload_user
    integer :: label = 0                   !< face number of Pn, n of Un
    real(dp) :: value = 0.0_dp             !< magnitude
    real(dp) :: dir(3) = 0.0_dp            !< direction of BX/BY/BZ/GRAV, axis of CENTRIF/ROTA (unit)
    real(dp) :: point(3) = 0.0_dp          !< CENTRIF/ROTA: a point on the axis
    integer :: amplitude = 0               !< amplitude index, 0 = the step's default
    integer :: elset = 0                   !< element set of the data line (resolved in finish_model), 0: one element
    type(source_pos_t) :: pos
  end type dload_t

  !> One data line of *INITIAL CONDITIONS (TYPE=STRESS or SOLUTION): values for a list of elements.
  type :: initial_condition_t
    integer :: kind = 0                    !< init_stress, init_solution
    integer, allocatable :: elems(:)       !< element indices (a negative user id or empty until finish_model)
    integer :: elset = 0                   !< element set of the data line, 0: one element
    real(dp), allocatable :: values(:)     !< stress components (Abaqus order) or state variables
    logical :: user = .false.              !< USER: every continuum element's points from SIGINI / SDVINI
    type(source_pos_t) :: pos
  end type initial_condition_t

  !> One *EQUATION: terms (node list, dof, coefficient in value); node sets expand into one equation per member.
  type :: equation_t
    type(cload_t), allocatable :: terms(:)
    integer, allocatable :: term_set(:)    !< per term: the node set it names (0: a node label), for set order
    logical :: mpc = .false.               !< written by *MPC (TIE): global components, not a node's *TRANSFORM
    type(source_pos_t) :: pos
  end type equation_t

  !> One *TIE pair: the nodes of the slave surface tied to the faces of the master surface.
  type :: tie_t
    character(len=name_len) :: name = ''
    integer :: slave = 0                   !< surface index
    integer :: master = 0                  !< surface index
    real(dp) :: tolerance = -1.0_dp        !< POSITION TOLERANCE (< 0: default, 5 % of the master face size)
    type(source_pos_t) :: pos
  end type tie_t

  !> *SURFACE, TYPE=ELEMENT: element faces.
  type :: surface_t
    character(len=name_len) :: name = ''   !< upper-case name
    integer, allocatable :: elems(:)       !< element indices (user ids, negative, or -huge for a set until finish)
    integer, allocatable :: faces(:)       !< face 1..6 per element
    integer, allocatable :: elsets(:)      !< per data line: element set index (0: one element)
    integer :: n = 0                       !< data lines
    integer, allocatable :: relems(:)      !< resolved element indices (finish_model), one per face
    integer, allocatable :: rfaces(:)      !< their faces
    type(source_pos_t) :: pos
  end type surface_t

  !> *COUPLING with *KINEMATIC or *DISTRIBUTING: the coupling nodes (of an element-based surface) constrained to a
  !> reference node (docs/host.md, "Coupling constraints").
  type :: coupling_t
    character(len=name_len) :: name = ''   !< CONSTRAINT NAME
    integer :: ref = 0                     !< reference node (negative label until finish_model, then its index)
    integer :: ref_set = 0                 !< REF NODE given as a node set (of one node): its index
    integer :: surface = 0                 !< element-based surface of the coupling nodes
    logical :: kinematic = .true.          !< *KINEMATIC (else *DISTRIBUTING)
    logical :: dofs(6) = .false.           !< constrained dofs (1..3 translations, local with ORIENTATION; 4..6)
    integer :: weighting = 1               !< *DISTRIBUTING, WEIGHTING METHOD: 1 uniform, 2 linear, 3 quadratic, 4 cubic
    real(dp) :: radius = -1.0_dp           !< INFLUENCE RADIUS (< 0: every node of the surface)
    character(len=name_len) :: orientation = '' !< ORIENTATION= ('' none): the constrained dofs' local system
    integer :: iorient = 0                 !< its index in model%orientations (finish_model)
    integer, allocatable :: nodes(:)       !< the coupling nodes (finish_model)
    type(source_pos_t) :: pos              !< the *COUPLING line
    type(source_pos_t) :: kind_pos         !< the *KINEMATIC or *DISTRIBUTING line
  end type coupling_t

  !> *PRE-TENSION SECTION with SURFACE=: the element-based surface that cuts a fastener and the pre-tension node
  !> whose dof 1 is the relative displacement of the two sides along the normal (docs/host.md, "Pre-tension
  !> sections"). The elements on the surface's side (the elements of its faces and the others on that side that
  !> share its nodes) see the section nodes' displacement plus u_p n: extra dofs, eliminated (pretension_sections).
  type :: pretension_t
    integer :: surface = 0                 !< element-based surface (index)
    integer :: node = 0                    !< pre-tension node (negative label until finish_model, then its index)
    integer :: node_set = 0                !< NODE= given as a node set (of one node): its index
    real(dp) :: normal(3) = 0.0_dp         !< unit normal (the data line's, or the faces' mean outward normal)
    logical :: normal_given = .false.      !< the data line gave it
    integer, allocatable :: nodes(:)       !< the section's nodes (finish_model)
    integer, allocatable :: elems(:)       !< the elements on the surface's side that hold section nodes
    integer :: dof0 = 0                    !< its extra dofs follow those of the earlier sections (ndim per node)
    type(source_pos_t) :: pos              !< the *PRE-TENSION SECTION line
  end type pretension_t

  !> One *MODEL CHANGE of a step: elements removed or added (docs/host.md, "Element removal and reactivation").
  type :: model_change_t
    integer, allocatable :: elems(:)       !< element indices (negative labels, and sets in elsets, until finish_model)
    integer, allocatable :: elsets(:)      !< element sets named on the data lines
    logical :: remove = .true.             !< REMOVE (else ADD)
    logical :: strain_free = .true.        !< ADD=STRAIN FREE (the default), else ADD=WITH STRAIN
    type(source_pos_t) :: pos              !< the *MODEL CHANGE line
  end type model_change_t

  !> *TIME POINTS: named step times for *OUTPUT, TIME POINTS= (the increments end on them).
  type :: time_points_t
    character(len=name_len) :: name = ''   !< upper-case name
    real(dp), allocatable :: t(:)          !< step times, ascending
  end type time_points_t

  !> One variable of a field output request (*OUTPUT, FIELD with VARIABLE=, *NODE OUTPUT, *ELEMENT OUTPUT),
  !> resolved against the output registry (host/output/output_registry.f90) while reading.
  type :: output_request_t
    integer :: var = 0                     !< output_registry index (OV_*)
    integer :: comp = 0                    !< SDVn: n (0: every state variable)
    type(source_pos_t) :: pos              !< the line that asked for it
  end type output_request_t

  !> *NODE PRINT request: one CSV column per variable (set totals) and a table in JOB.dat.
  type :: node_print_t
    character(len=name_len) :: nset = ''   !< set name
    integer :: set_index = 0               !< index into model%nsets (0: every node, JOB.dat only)
    character(len=8), allocatable :: vars(:) !< RF1..RF3, U1..U3
    integer :: frequency = 1               !< FREQUENCY (increments; 0: none; the step's last always)
    logical :: totals = .false.            !< TOTALS=YES: a TOTAL line under the table
    logical :: summary = .true.            !< SUMMARY=YES (default): MAXIMUM/MINIMUM lines
    logical :: global = .false.            !< GLOBAL=YES: global components at *TRANSFORM nodes (default local)
    type(source_pos_t) :: pos              !< the *NODE PRINT line
  end type node_print_t

  !> *EL PRINT request: a table of integration-point values in JOB.dat.
  type :: el_print_t
    character(len=name_len) :: elset = ''  !< set name ('' : every continuum element)
    integer :: set_index = 0               !< index into model%elsets (0: every element)
    character(len=8), allocatable :: vars(:) !< S11..S23, MISES, LE11..LE23 / E11..E23, SDVn
    integer :: frequency = 1               !< FREQUENCY (increments; 0: none; the step's last always)
    logical :: totals = .false.            !< TOTALS=YES
    logical :: summary = .true.            !< SUMMARY=YES (default)
    type(source_pos_t) :: pos              !< the *EL PRINT line
  end type el_print_t

  type :: step_t
    character(len=name_len) :: name = ''
    logical :: nlgeom = .false.            !< NLGEOM=YES
    integer :: max_inc = 100               !< INC=
    real(dp) :: dt_initial = 1.0_dp        !< *STATIC data
    real(dp) :: period = 1.0_dp
    real(dp) :: dt_min = 1.0e-5_dp
    real(dp) :: dt_max = 1.0_dp
    logical :: direct = .false.            !< *STATIC, DIRECT: fixed increments
    logical :: extrapolate = .true.        !< *STEP, EXTRAPOLATION=LINEAR (Abaqus' default) or PARABOLIC; NO: false
    logical :: parabolic = .false.         !< *STEP, EXTRAPOLATION=PARABOLIC: quadratic through the last two increments
    logical :: unsymm = .false.            !< *STEP, UNSYMM=YES: unsymmetric solver
    logical :: op_new = .false.            !< a *BOUNDARY, OP=NEW in this step removes inherited boundaries
    logical :: amp_step = .false.          !< *STEP, AMPLITUDE=STEP (default RAMP: loads vary linearly over the step)
    logical :: cload_op_new = .false.      !< a *CLOAD, OP=NEW in this step removes inherited concentrated loads
    type(cload_t), allocatable :: cloads(:)!< concentrated loads given in this step
    integer :: ncload = 0
    logical :: dload_op_new = .false.      !< a *DLOAD/*DSLOAD, OP=NEW in this step removes inherited distributed loads
    type(dload_t), allocatable :: dloads(:)!< distributed loads given in this step
    integer :: ndload = 0
    type(cload_t), allocatable :: temps(:) !< *TEMPERATURE lines (node list, value; dof = 1)
    integer :: ntemp = 0
    type(cload_t), allocatable :: fields(:) !< *FIELD lines (node list, value; dof = VARIABLE)
    integer :: nfielddef = 0
    integer, allocatable :: field_new(:)   !< the VARIABLEs of a *FIELD, OP=NEW in this step
    integer :: max_iter = 16               !< *CONTROLS, PARAMETERS=TIME INCREMENTATION: I_A (here the iteration cap)
    real(dp) :: r_n = 0.005_dp             !< *CONTROLS, PARAMETERS=FIELD: R_n
    real(dp) :: c_n = 0.01_dp              !< *CONTROLS, PARAMETERS=FIELD: C_n
    type(boundary_t), allocatable :: bcs(:)!< boundaries given in this step
    integer :: nbc = 0
    logical :: field_output = .false.      !< *OUTPUT, FIELD present
    integer :: field_frequency = 1         !< FREQUENCY (increments), 0 = last only
    integer :: field_intervals = 0         !< NUMBER INTERVAL (0 = not given)
    logical :: field_given = .false.       !< this step has its own *OUTPUT, FIELD (otherwise the previous step's
                                           !< field request stays in effect, as in Abaqus)
    logical :: field_op_new = .false.      !< *OUTPUT, FIELD, OP=NEW: earlier requests do not carry over
    logical :: field_vars_named = .false.  !< variables were named (VARIABLE=, *ELEMENT/*NODE OUTPUT data lines)
    !> the variables the field request names (output registry), with the lines that named them; a step without
    !> its own request carries the previous step's (deck_finish)
    type(output_request_t), allocatable :: field_requests(:)
    integer :: nfield_request = 0
    type(node_print_t), allocatable :: prints(:)
    integer :: nprint = 0
    type(el_print_t), allocatable :: elprints(:) !< *EL PRINT requests
    integer :: nelprint = 0
    integer :: restart_frequency = 0       !< *RESTART, WRITE, FREQUENCY=n in effect (0: no restart file)
    real(dp), allocatable :: field_points(:) !< *OUTPUT, FIELD, TIME POINTS=: step times of the frames
    real(dp), allocatable :: history_points(:) !< *OUTPUT, HISTORY, TIME POINTS=: step times
    logical :: history_given = .false.     !< this step has its own *OUTPUT, HISTORY (else the previous one's holds)
    real(dp), allocatable :: cut_points(:) !< step times the increments end on (the field and history points in
                                           !< effect, finish_model)
    logical :: field_points_given = .false. !< this step's own *OUTPUT, FIELD names TIME POINTS
    type(model_change_t), allocatable :: changes(:) !< *MODEL CHANGE of this step, in deck order
    integer :: nchange = 0
    type(source_pos_t) :: pos
  end type step_t

  !> A part instance flattened into the model (*ASSEMBLY/*INSTANCE): model label = part label + offset.
  type :: instance_t
    character(len=name_len) :: name = ''   !< upper-case instance name
    character(len=name_len) :: part = ''   !< upper-case part name
    integer :: node_offset = 0             !< model node label = part node label + node_offset
    integer :: elem_offset = 0             !< model element label = part element label + elem_offset
    integer :: node_last = 0               !< largest model node label of the instance
    integer :: elem_last = 0               !< largest model element label of the instance
  end type instance_t

  type :: model_t
    character(len=:), allocatable :: heading
    integer :: ndim = 0                    !< 2 or 3 (from the element types)
    ! nodes
    integer :: nnode = 0
    integer, allocatable :: node_id(:)     !< user node numbers
    real(dp), allocatable :: x(:,:)        !< (3, nnode) original coordinates
    integer, allocatable :: node_index(:)  !< user id -> index (0 = undefined), sized max id
    ! elements
    integer :: nelem = 0
    integer, allocatable :: elem_id(:)     !< user element numbers
    integer, allocatable :: elem_kind(:)   !< element_catalog kind (continuum) or etype_user
    integer, allocatable :: elem_utype(:)  !< index into utypes for user elements
    integer, allocatable :: conn_ptr(:)    !< (nelem+1) CSR pointers into conn
    integer, allocatable :: conn(:)        !< node indices
    integer, allocatable :: elem_section(:)!< section index (continuum)
    integer, allocatable :: elem_uelprop(:)!< index into uel_props (user)
    integer, allocatable :: elem_index(:)  !< user element id -> index
    ! sets and definitions
    type(node_set_t), allocatable :: nsets(:)
    integer :: n_nset = 0
    type(elem_set_t), allocatable :: elsets(:)
    integer :: n_elset = 0
    type(material_t), allocatable :: materials(:)
    integer :: nmat = 0
    type(section_t), allocatable :: sections(:)
    integer :: nsection = 0
    type(user_element_type_t), allocatable :: utypes(:)
    integer :: nutype = 0
    type(uel_property_t), allocatable :: uelprops(:) !< *UEL PROPERTY blocks
    integer :: n_uelprop = 0
    type(amplitude_t), allocatable :: amplitudes(:)
    integer :: namp = 0
    type(surface_t), allocatable :: surfaces(:)
    integer :: nsurf = 0
    type(initial_condition_t), allocatable :: inits(:) !< *INITIAL CONDITIONS data lines, in deck order
    integer :: ninit = 0
    type(cload_t), allocatable :: temp_inits(:) !< *INITIAL CONDITIONS, TYPE=TEMPERATURE lines (dof = 1)
    integer :: ntemp_init = 0
    type(cload_t), allocatable :: field_inits(:) !< *INITIAL CONDITIONS, TYPE=FIELD lines (dof = VARIABLE)
    integer :: nfield_init = 0
    integer :: nfield = 0                  !< field variables of the model (the highest VARIABLE given)
    type(equation_t), allocatable :: equations(:) !< *EQUATION
    integer :: nequation = 0
    type(tie_t), allocatable :: ties(:)    !< *TIE
    integer :: ntie = 0
    type(boundary_t), allocatable :: initial_bcs(:) !< model-data *BOUNDARY (fixed, value 0 or given)
    integer :: n_initial_bc = 0
    type(step_t), allocatable :: steps(:)
    integer :: nstep = 0
    type(instance_t), allocatable :: instances(:) !< part instances flattened into the model (label map)
    integer :: ninstance = 0
    type(orientation_t), allocatable :: orientations(:) !< *ORIENTATION definitions
    integer :: norient = 0
    type(transform_t), allocatable :: transforms(:) !< *TRANSFORM definitions
    integer :: ntransform = 0
    integer, allocatable :: node_transform(:) !< (nnode) the *TRANSFORM of a node (0: global system)
    type(coupling_t), allocatable :: couplings(:) !< *COUPLING definitions
    integer :: ncoupling = 0
    !> (nnode) the first of a node's rotational dofs (the reference node of a coupling that has them: 3 in 3D, 1 in
    !> 2D), counted after the ndim*nnode displacement dofs; 0: none (model_dof)
    integer, allocatable :: node_rot(:)
    integer :: nrot = 0                    !< rotational dofs of the model
    type(pretension_t), allocatable :: pretensions(:) !< *PRE-TENSION SECTION definitions
    integer :: npretension = 0
    integer :: npret_dof = 0               !< extra dofs of the sections (after the nodes' and the rotations')
    type(time_points_t), allocatable :: time_points(:) !< *TIME POINTS definitions
    integer :: ntime_points = 0
    logical :: has_model_change = .false.  !< some step has a *MODEL CHANGE
    integer :: monitor_node = 0            !< *MONITOR, NODE= (model label while reading, node index after; 0: none)
    integer :: monitor_dof = 0             !< *MONITOR, DOF=
    type(source_pos_t) :: monitor_pos      !< where *MONITOR is
  end type model_t

contains

  !> A model node (is_node) or element label as the deck wrote it: 'INSTANCE.label' for a label of a part
  !> instance, the label itself otherwise.
  pure function model_label_text(model, id, is_node) result(t)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: id           !< model label
    logical, intent(in) :: is_node      !< node (true) or element label
    character(len=:), allocatable :: t
    character(len=16) :: b
    integer :: k
    write (b, '(i0)') id
    t = trim(b)
    do k = 1, model%ninstance
      associate (in => model%instances(k))
        if (is_node) then
          if (id <= in%node_offset .or. id > in%node_last) cycle
          write (b, '(i0)') id - in%node_offset
        else
          if (id <= in%elem_offset .or. id > in%elem_last) cycle
          write (b, '(i0)') id - in%elem_offset
        end if
        t = trim(in%name)//'.'//trim(b)//' (model label '//t//')'
        return
      end associate
    end do
  end function model_label_text

  !> The global index of dof d (1..6, Abaqus numbering) of node i: the displacement dofs (i-1)*ndim + d for
  !> d <= ndim; a rotational dof 4..6 (3D) or 6 (2D) of a coupling's reference node after the displacement dofs; 0
  !> when the node has no such dof.
  pure integer function model_dof(model, i, d) result(k)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: i            !< node index
    integer, intent(in) :: d            !< dof 1..6
    k = 0
    if (d >= 1 .and. d <= model%ndim) then
      k = (i - 1) * model%ndim + d
      return
    end if
    if (.not. allocated(model%node_rot)) return
    if (model%node_rot(i) == 0) return
    if (model%ndim == 3 .and. d >= 4 .and. d <= 6) k = model%ndim * model%nnode + model%node_rot(i) + d - 4
    if (model%ndim == 2 .and. d == 6) k = model%ndim * model%nnode + model%node_rot(i)
  end function model_dof

  !> The node of global dof k (model_dof's inverse): a rotational dof belongs to its reference node.
  pure integer function model_dof_node(model, k) result(i)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: k            !< global dof
    integer :: j, nr
    if (k <= model%ndim * model%nnode) then
      i = (k - 1) / model%ndim + 1
      return
    end if
    nr = merge(3, 1, model%ndim == 3)
    j = k - model%ndim * model%nnode
    do i = 1, model%nnode
      if (model%node_rot(i) == 0) cycle
      if (j >= model%node_rot(i) .and. j < model%node_rot(i) + nr) return
    end do
    i = 0
  end function model_dof_node

  !> Index of a *TIME POINTS definition by (upper-case) name, 0 if absent.
  pure integer function model_find_time_points(model, name) result(k)
    type(model_t), intent(in) :: model  !< the model
    character(len=*), intent(in) :: name!< upper-case name
    do k = 1, model%ntime_points
      if (model%time_points(k)%name == name) return
    end do
    k = 0
  end function model_find_time_points

  !> Local axes (columns, unit, right-handed) of orientation o at point x (model coordinates); a, b, c resolved.
  !> RECTANGULAR: 1 along a - c, 3 normal to the plane of a, b, c, 2 = 3 x 1. CYLINDRICAL: 3 along the axis a -> b,
  !> 1 radial from the axis through x, 2 = 3 x 1. SPHERICAL (system 3): 1 radial from the centre a, 3 along
  !> (b - a) x (x - a) (azimuthal), 2 = 3 x 1. Then the additional rotation about local axis extra_axis.
  !> ok = .false. when the axes are undefined (coinciding points, x on the cylinder axis).
  pure subroutine orientation_axes(o, x, t, ok)
    type(orientation_t), intent(in) :: o  !< the orientation
    real(dp), intent(in) :: x(3)          !< the point
    real(dp), intent(out) :: t(3, 3)      !< axes as columns
    logical, intent(out) :: ok            !< defined
    real(dp) :: e1(3), e2(3), e3(3), r(3), th, co, si, tt(3, 3)
    integer :: i, j
    real(dp), parameter :: tiny_len = 1.0e-12_dp
    t = 0.0_dp
    ok = .false.
    if (o%system == 1) then
      e1 = o%a - o%c
      e3 = cross(e1, o%b - o%c)
    else if (o%system == 3) then
      ! SPHERICAL (centre a, polar axis a -> b): 1 radial, 3 = azimuthal (about the polar axis), 2 = 3 x 1 (the
      ! polar-angle direction); undefined at the centre and on the polar axis
      r = x - o%a
      e3 = o%b - o%a
      if (norm2(e3) <= tiny_len * max(1.0_dp, norm2(o%a)) .or. norm2(r) <= tiny_len * max(1.0_dp, norm2(x))) return
      e1 = r
      e3 = cross(e3 / norm2(e3), r / norm2(r))
      if (norm2(e3) <= tiny_len) return
    else
      e3 = o%b - o%a
      if (norm2(e3) <= tiny_len * max(1.0_dp, norm2(o%a))) return
      e3 = e3 / norm2(e3)
      r = x - o%a
      e1 = r - dot_product(r, e3) * e3
    end if
    if (norm2(e1) <= tiny_len * max(1.0_dp, norm2(x)) .or. norm2(e3) <= tiny_len**2 * max(1.0_dp, norm2(x))**2) &
      return
    e1 = e1 / norm2(e1)
    e3 = e3 / norm2(e3)
    e2 = cross(e3, e1)
    t(:, 1) = e1
    t(:, 2) = e2
    t(:, 3) = e3
    if (o%extra_axis >= 1 .and. o%extra_axis <= 3 .and. o%extra_angle /= 0.0_dp) then
      ! rotation by the angle about local axis extra_axis (right-handed): the other two axes turn
      th = o%extra_angle * acos(-1.0_dp) / 180.0_dp
      co = cos(th)
      si = sin(th)
      i = mod(o%extra_axis, 3) + 1
      j = mod(o%extra_axis + 1, 3) + 1
      tt = t
      t(:, i) = co * tt(:, i) + si * tt(:, j)
      t(:, j) = -si * tt(:, i) + co * tt(:, j)
    end if
    ok = .true.
  contains
    pure function cross(p, q) result(w)
      real(dp), intent(in) :: p(3), q(3)
      real(dp) :: w(3)
      w = [p(2) * q(3) - p(3) * q(2), p(3) * q(1) - p(1) * q(3), p(1) * q(2) - p(2) * q(1)]
    end function cross
  end subroutine orientation_axes

  !> Index of a node set by (upper-case) name, 0 if absent.
  pure integer function model_find_nset(model, name) result(k)
    type(model_t), intent(in) :: model  !< the model
    character(len=*), intent(in) :: name!< upper-case name
    do k = 1, model%n_nset
      if (model%nsets(k)%name == name) return
    end do
    k = 0
  end function model_find_nset

  !> Index of an *ORIENTATION by (upper-case) name, 0 if absent.
  pure integer function model_find_orientation(model, name) result(k)
    type(model_t), intent(in) :: model  !< the model
    character(len=*), intent(in) :: name!< upper-case name
    do k = 1, model%norient
      if (model%orientations(k)%name == name) return
    end do
    k = 0
  end function model_find_orientation

  !> Index of an element set by (upper-case) name, 0 if absent.
  pure integer function model_find_elset(model, name) result(k)
    type(model_t), intent(in) :: model  !< the model
    character(len=*), intent(in) :: name!< upper-case name
    do k = 1, model%n_elset
      if (model%elsets(k)%name == name) return
    end do
    k = 0
  end function model_find_elset

  !> Index of a material by (upper-case) name, 0 if absent.
  pure integer function model_find_material(model, name) result(k)
    type(model_t), intent(in) :: model  !< the model
    character(len=*), intent(in) :: name!< upper-case name
    do k = 1, model%nmat
      if (model%materials(k)%name == name) return
    end do
    k = 0
  end function model_find_material

  !> Index of an amplitude by (upper-case) name, 0 if absent.
  pure integer function model_find_amplitude(model, name) result(k)
    type(model_t), intent(in) :: model  !< the model
    character(len=*), intent(in) :: name!< upper-case name
    do k = 1, model%namp
      if (model%amplitudes(k)%name == name) return
    end do
    k = 0
  end function model_find_amplitude

  !> Index of a surface by (upper-case) name, 0 if absent.
  pure integer function model_find_surface(model, name) result(k)
    type(model_t), intent(in) :: model  !< the model
    character(len=*), intent(in) :: name!< upper-case name
    do k = 1, model%nsurf
      if (model%surfaces(k)%name == name) return
    end do
    k = 0
  end function model_find_surface

  !> Index of a user element type by (upper-case) name, 0 if absent.
  pure integer function model_find_user_type(model, name) result(k)
    type(model_t), intent(in) :: model  !< the model
    character(len=*), intent(in) :: name!< upper-case name (U1, ...)
    do k = 1, model%nutype
      if (model%utypes(k)%name == name) return
    end do
    k = 0
  end function model_find_user_type

  !> Amplitude at step time t_step of a step that began at total time t_total0 (TIME=TOTAL TIME reads the curve at
  !> t_total0 + t_step).
  pure real(dp) function amplitude_factor(amp, t_step, t_total0) result(a)
    type(amplitude_t), intent(in) :: amp  !< amplitude
    real(dp), intent(in) :: t_step        !< step time
    real(dp), intent(in) :: t_total0      !< total time at the start of the step
    if (amp%total_time) then
      a = amplitude_value(amp, t_total0 + t_step)
    else
      a = amplitude_value(amp, t_step)
    end if
  end function amplitude_factor

  !> Tabular amplitude at time t (constant beyond the ends, as Abaqus): piecewise linear, or for DEFINITION=SMOOTH
  !> STEP the fifth-order polynomial of Abaqus between consecutive points, a_i + (a_i+1 - a_i) xi^3 (10 - 15 xi +
  !> 6 xi^2), xi = (t - t_i) / (t_i+1 - t_i), whose first and second derivatives vanish at every data point.
  pure real(dp) function amplitude_value(amp, t) result(a)
    type(amplitude_t), intent(in) :: amp  !< tabular amplitude
    real(dp), intent(in) :: t             !< step time (total time for TIME=TOTAL TIME)
    integer :: i, n
    real(dp) :: xi
    n = size(amp%t)
    if (n == 0) then
      a = 1.0_dp
      return
    end if
    if (t <= amp%t(1)) then
      a = amp%a(1)
      return
    end if
    do i = 2, n
      if (t <= amp%t(i)) then
        if (amp%t(i) > amp%t(i - 1)) then
          xi = (t - amp%t(i - 1)) / (amp%t(i) - amp%t(i - 1))
          if (amp%smooth) xi = xi**3 * (10.0_dp - 15.0_dp * xi + 6.0_dp * xi**2)
          a = amp%a(i - 1) + (amp%a(i) - amp%a(i - 1)) * xi
        else
          a = amp%a(i)
        end if
        return
      end if
    end do
    a = amp%a(n)
  end function amplitude_value

  !> Output name of state variable k: 'SDV_key' when every material that names it (*DEPVAR key) gives it the same
  !> key, as Abaqus names the field output of a named state variable; 'SDVk' otherwise. Characters other than
  !> letters, digits, '_' and '-' become '_' (the name is an XML attribute in the VTU frames).
  function model_sdv_name(model, k) result(name)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: k            !< state variable number
    character(len=:), allocatable :: name, key
    character(len=16) :: b
    integer :: im, i
    key = ''
    do im = 1, model%nmat
      if (.not. allocated(model%materials(im)%sdv_key)) cycle
      if (k > size(model%materials(im)%sdv_key)) cycle
      if (len_trim(model%materials(im)%sdv_key(k)) == 0) cycle
      if (len(key) > 0 .and. key /= trim(model%materials(im)%sdv_key(k))) then
        key = ''
        exit
      end if
      key = trim(model%materials(im)%sdv_key(k))
    end do
    write (b, '(i0)') k
    if (len(key) == 0) then
      name = 'SDV'//trim(b)
      return
    end if
    do i = 1, len(key)
      if (verify(key(i:i), 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-') /= 0) key(i:i) = '_'
    end do
    name = 'SDV_'//key
  end function model_sdv_name

  !> Elements may leave the model during the analysis: *MODEL CHANGE, or a material deleting failed points
  !> (*DEPVAR, DELETE=); the analysis then keeps the active set (analysis_state).
  pure logical function model_elements_leave(model) result(yes)
    type(model_t), intent(in) :: model  !< the model
    yes = model%has_model_change
    if (model%nmat > 0) yes = yes .or. any(model%materials(1:model%nmat)%delete_sdv > 0)
  end function model_elements_leave

end module model_types
