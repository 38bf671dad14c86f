!     ldfcz: MSC.Marc HYPELA2 entry point of the compressible Leonov
!     model. Not part of ldfcz's libraries: it includes Marc's common
!     blocks 'concom' and 'creeps' (for the time increment timinc),
!     which only a Marc installation provides (the tests build it
!     against test doubles, tests/support/marc). Compile it together
!     with umat/leonov_parameters.f90, leonov.f90, leonov_marc.f90
!     in Marc's user-subroutine build (for example
!     run_marc -user hypela2.f, with the modules compiled first).
!
!     Marc data (unverified parts marked in docs/umat.md):
!       - update-Lagrange large strain ('PLASTICITY,3' or
!         'LARGE STRAIN'): s Cauchy stress, d tangent as Abaqus
!         DDSDDE, shear order 11,22,33,12,23,31 (inferred).
!       - HYPELA2 has no property argument: the properties are
!         Table 1 of the paper (PET) below; edit PROPS to change.
!       - STATE VARS >= 12: t(1) is the temperature, t(2:12) the
!         Leonov state (layout of the UMAT's STATEV 1-11). That Marc
!         keeps values written to t as the state at t_n+1 is stated
!         in the Marc header comment ("must be updated") but not
!         verified here.
!       - A core failure (or dgamma_p > 0.05) cannot request a
!         cutback through HYPELA2's arguments; it is reported with
!         a message and the increment continues (unverified: use
!         Marc's own step control, e.g. UTIMESTEP, to cut back).
      SUBROUTINE HYPELA2(D,G,E,DE,S,T,DT,NGENS,M,NN,KCUS,MATUS,NDI,
     1 NSHEAR,DISP,DISPT,COORD,FFN,FROTN,STRECHN,EIGVN,FFN1,FROTN1,
     2 STRECHN1,EIGVN1,NCRD,ITEL,NDEG,NDM,NNODE,JTYPE,LCLASS,IFR,IFU)
      USE LEONOV_PARAMETERS, ONLY: LEONOV_PROPS_TABLE1
      USE LEONOV_MARC, ONLY: LEONOV_MARC_UPDATE
      IMPLICIT REAL*8 (A-H, O-Z)
      INCLUDE 'concom'
      INCLUDE 'creeps'
      DIMENSION E(*),DE(*),T(*),DT(*),G(*),D(NGENS,*),S(*),M(2),
     1 COORD(NCRD,*),DISP(NDEG,*),MATUS(2),DISPT(NDEG,*),
     2 FFN(ITEL,*),FROTN(ITEL,*),STRECHN(ITEL),EIGVN(ITEL,*),
     3 FFN1(ITEL,*),FROTN1(ITEL,*),STRECHN1(ITEL),EIGVN1(ITEL,*),
     4 KCUS(2),LCLASS(2)
      DOUBLE PRECISION PROPS(10), FACTOR
      INTEGER ISTAT
      CHARACTER(LEN=256) MSG
      PROPS = LEONOV_PROPS_TABLE1()
      CALL LEONOV_MARC_UPDATE(PROPS, FFN(1:ITEL,1:ITEL),
     1 FFN1(1:ITEL,1:ITEL), ITEL, TIMINC, NGENS, NDI, NSHEAR,
     2 T(2:12), S(1:NGENS), D(1:NGENS,1:NGENS), ISTAT, FACTOR, MSG)
      IF (ISTAT .EQ. 3) THEN
        WRITE (*, '(A)') TRIM(MSG)
        CALL QUIT(13)
      ELSE IF (ISTAT .NE. 0) THEN
        WRITE (*, '(A,I0,A,I0,A,ES10.3)') 'HYPELA2 (Leonov): element ',
     1   M(1), ' point ', NN, ': smaller time step advised, factor ',
     2   FACTOR
      END IF
      RETURN
      END SUBROUTINE HYPELA2
