!     ldfcz: MSC.Marc USELEM entry point of the LDF cohesive element
!     (van den Bosch, Schreurs, Geers 2007, sections 4-5), the paper's
!     own host. Thin: hands the calls it does not compute back to
!     Marc, fetches the update flag and the time increment from Marc's
!     common blocks, and calls module cohesive_marc, which unpacks the
!     arrays and calls the same core as the Abaqus UEL. Not part of
!     ldfcz's libraries: LDFCZ_MARC_CONTROL includes Marc's 'concom'
!     and 'creeps', which only a Marc installation provides (the tests
!     build it against test doubles, tests/support/marc).
!
!     Argument list as Marc Volume D gives it and its public example
!     uses; what each argument carries and every assumption is listed
!     in docs/uel.md, "MSC.Marc: USELEM" (inferred parts marked there):
!       IFLAG 2 and 4: XK = dR/du (IDSS x IDSS, node-major, NDEG dofs
!         per node) and R = internal force (NDEG x NNODE) from the
!         total displacement DISPT + DISP; T(2:5,ip) the history.
!       IFLAG 1, 3, 5: not computed here; JTYPE = -JTYPE hands the
!         call to Marc's own routine (as the public example does).
!       Element: NNODE = 8 with NCRD, NDEG >= 3 (3D) or NNODE = 4 with
!         NCRD, NDEG >= 2 (plane); node numbering of the UEL.
!       Properties: GEOM(1) phi, GEOM(2) delta, GEOM(3) k_c (Marc's
!         GEOMETRY option); the other UEL properties from OPTR, OPTI
!         below (0 = default; edit them to change).
!       State: STATE VARS >= 5; T(1,ip) temperature (untouched),
!         T(2:5,ip) Delta_max, |Delta|, |T|, Delta_c (the UEL's SVARS
!         of point ip).
!     Bad input or a failed element: a message and QUIT(13) (USELEM
!     has no argument to request a smaller step).
      SUBROUTINE USELEM(M,XK,XM,NNODE,NDEG,F,R,JTYPE,DISPT,DISP,
     1 NDI,NSHEAR,JPASS,NSTATS,NGENEL,INTEL,COORD,NCRD,IFLAG,IDSS,
     2 T,DT,ETOTA,GSIGS,DE,GEOM,JGEOM,SIGXX,NSTRMU)
      USE COHESIVE_MARC, ONLY: COHESIVE_MARC_ELEMENT, MARC_OK
      IMPLICIT NONE
      INTEGER M, NNODE, NDEG, JTYPE, NDI, NSHEAR, JPASS, NSTATS
      INTEGER NGENEL, INTEL, NCRD, IFLAG, IDSS, JGEOM, NSTRMU
      DOUBLE PRECISION XK, XM, F, R, DISPT, DISP, T, DT, ETOTA
      DOUBLE PRECISION GSIGS, DE, GEOM, COORD, SIGXX
      DIMENSION XK(IDSS,IDSS),XM(IDSS,IDSS),DISPT(NDEG,*),
     1 DISP(NDEG,*),T(NSTATS,*),DT(NSTATS,*),COORD(NCRD,*),
     2 ETOTA(NGENEL,*),GSIGS(NGENEL,*),DE(NGENEL,*),F(NDEG,*),
     3 R(NDEG,*),SIGXX(NSTRMU,*),GEOM(*),JGEOM(*)
!     UEL properties that Marc's GEOMETRY does not carry (0: default):
!     OPTR = PROPS(4:7): phi_t, delta_t (classical law), eta_v
!     (N s/mm^3), thickness of the plane element; OPTI = JPROPS(1:3):
!     unloading (1 reversible, 2 damage, 3 plastic), law (1 LDF,
!     2 classical), 1 axisymmetric. docs/uel.md lists them.
      DOUBLE PRECISION OPTR(4)
      INTEGER OPTI(3)
      PARAMETER (OPTR = (/ 0.0D0, 0.0D0, 0.0D0, 0.0D0 /))
      PARAMETER (OPTI = (/ 0, 0, 0 /))
      DOUBLE PRECISION PROPS(7), TINC
      INTEGER JUPD, ISTAT
      CHARACTER*256 EMSG
!
      IF (IFLAG .EQ. 1 .OR. IFLAG .EQ. 3 .OR. IFLAG .EQ. 5) THEN
        JTYPE = -JTYPE
        RETURN
      ELSE IF (IFLAG .NE. 2 .AND. IFLAG .NE. 4) THEN
        WRITE (*, '(A,I0,A,I0,A)') 'USELEM ldfcz: element ', M,
     1   ': IFLAG = ', IFLAG, ' not known (1 to 5 are)'
        CALL QUIT(13)
        RETURN
      END IF
      CALL LDFCZ_MARC_CONTROL(JUPD, TINC)
      PROPS(1:3) = GEOM(1:3)
      PROPS(4:7) = OPTR
      CALL COHESIVE_MARC_ELEMENT(PROPS, OPTI,
     1 COORD(1:NCRD,1:NNODE), DISPT(1:NDEG,1:NNODE),
     2 DISP(1:NDEG,1:NNODE), JUPD .EQ. 1, TINC,
     3 T(1:NSTATS,1:INTEL), XK(1:IDSS,1:IDSS), R(1:NDEG,1:NNODE),
     4 ISTAT, EMSG)
      IF (ISTAT .NE. MARC_OK) THEN
        WRITE (*, '(A,I0,A)') 'USELEM ldfcz: element ', M, ': '
     1   //TRIM(EMSG)
        CALL QUIT(13)
      END IF
      RETURN
      END SUBROUTINE USELEM

!     Marc's updated Lagrange flag IUPDAT (common block 'concom') and
!     time increment TIMINC ('creeps'), read in a routine of their
!     own so that no name of USELEM can meet a name of Marc's commons.
      SUBROUTINE LDFCZ_MARC_CONTROL(LZUPDT, LZTINC)
      IMPLICIT REAL*8 (A-H, O-Z)
      INCLUDE 'concom'
      INCLUDE 'creeps'
      INTEGER LZUPDT
      DOUBLE PRECISION LZTINC
      LZUPDT = IUPDAT
      LZTINC = TIMINC
      RETURN
      END SUBROUTINE LDFCZ_MARC_CONTROL
