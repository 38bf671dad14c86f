!     ldfcz test doubles of the Marc environment HYPELA2 runs in:
!     MARC_TEST_SET sets the common blocks of the include-file doubles
!     (time increment, updated Lagrange flag); QUIT records its code
!     instead of ending the program (MARC_TEST_QUIT_CODE reads it).
      SUBROUTINE MARC_TEST_SET(DTIME, JUPDAT)
      IMPLICIT REAL*8 (A-H, O-Z)
      INCLUDE 'concom'
      INCLUDE 'creeps'
      DOUBLE PRECISION, INTENT(IN) :: DTIME
      INTEGER, INTENT(IN) :: JUPDAT
      TIMINC = DTIME
      CPTIM = 0.0D0
      IUPDAT = JUPDAT
      CALL MARC_TEST_QUIT_RESET()
      END SUBROUTINE MARC_TEST_SET

      SUBROUTINE QUIT(ICODE)
      IMPLICIT NONE
      INTEGER, INTENT(IN) :: ICODE
      INTEGER LASTQ
      COMMON /MARCTQ/ LASTQ
      LASTQ = ICODE
      END SUBROUTINE QUIT

      SUBROUTINE MARC_TEST_QUIT_RESET()
      IMPLICIT NONE
      INTEGER LASTQ
      COMMON /MARCTQ/ LASTQ
      LASTQ = 0
      END SUBROUTINE MARC_TEST_QUIT_RESET

      INTEGER FUNCTION MARC_TEST_QUIT_CODE()
      IMPLICIT NONE
      INTEGER LASTQ
      COMMON /MARCTQ/ LASTQ
      MARC_TEST_QUIT_CODE = LASTQ
      END FUNCTION MARC_TEST_QUIT_CODE
