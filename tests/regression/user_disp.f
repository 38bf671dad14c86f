C     A fixed-form DISP for test deck_boundary_user: records every call in <output directory>/disp_calls.txt
C     (NODE, JDOF, KSTEP, KINC, NOEL, TIME(1:3), COORDS(1:3) and the U(1) passed in) and returns twice the
C     value passed in plus 0.001 times the node's x coordinate: U(1) = 2 U(1) + 0.001 COORDS(1).
      SUBROUTINE DISP(U,KSTEP,KINC,TIME,NODE,NOEL,JDOF,COORDS)
      INCLUDE 'ABA_PARAM.INC'
      DIMENSION U(3),TIME(3),COORDS(3)
      CHARACTER*256 OUTDIR
      INTEGER LENOUT, IU
      CALL GETOUTDIR(OUTDIR, LENOUT)
      OPEN(NEWUNIT=IU, FILE=OUTDIR(1:LENOUT)//'/disp_calls.txt',
     1 POSITION='APPEND', ACTION='WRITE')
      WRITE(IU,'(5(I0,1X),7(ES24.16,1X))') NODE, JDOF, KSTEP, KINC,
     1 NOEL, TIME(1), TIME(2), TIME(3), COORDS(1), COORDS(2),
     2 COORDS(3), U(1)
      CLOSE(IU)
      U(1) = 2.0D0*U(1) + 0.001D0*COORDS(1)
      RETURN
      END
