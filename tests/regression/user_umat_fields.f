C     A fixed-form user UMAT that records the predefined fields the host passes on every call (test
C     deck_fields): one line per call in <output directory>/umat_fields.txt with NOEL, NPT, KSTEP, KINC,
C     TIME, DTIME, TEMP, DTEMP, COORDS, PREDEF(1:2) and DPRED(1:2) (the deck defines two field variables,
C     so PREDEF and DPRED hold two values: Abaqus passes arrays of the number of field variables), then
C     small-strain isotropic elasticity (PROPS(1) = E, PROPS(2) = nu). Run with --threads 1.
      SUBROUTINE UMAT(STRESS,STATEV,DDSDDE,SSE,SPD,SCD,
     1 RPL,DDSDDT,DRPLDE,DRPLDT,
     2 STRAN,DSTRAN,TIME,DTIME,TEMP,DTEMP,PREDEF,DPRED,CMNAME,
     3 NDI,NSHR,NTENS,NSTATV,PROPS,NPROPS,COORDS,DROT,PNEWDT,
     4 CELENT,DFGRD0,DFGRD1,NOEL,NPT,LAYER,KSPT,JSTEP,KINC)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*80 CMNAME
      DIMENSION STRESS(NTENS),STATEV(NSTATV),
     1 DDSDDE(NTENS,NTENS),DDSDDT(NTENS),DRPLDE(NTENS),
     2 STRAN(NTENS),DSTRAN(NTENS),TIME(2),PREDEF(*),DPRED(*),
     3 PROPS(NPROPS),COORDS(3),DROT(3,3),DFGRD0(3,3),DFGRD1(3,3),
     4 JSTEP(4)
      CHARACTER*256 OUTDIR
      INTEGER LENOUT, IU
      CALL GETOUTDIR(OUTDIR, LENOUT)
      OPEN(NEWUNIT=IU, FILE=OUTDIR(1:LENOUT)//'/umat_fields.txt',
     1 POSITION='APPEND', ACTION='WRITE')
      WRITE(IU,'(4(I0,1X),12(ES24.16,1X))') NOEL, NPT, JSTEP(1), KINC,
     1 TIME(1), TIME(2), DTIME, TEMP, DTEMP, (COORDS(I), I = 1, 3),
     2 PREDEF(1), PREDEF(2), DPRED(1), DPRED(2)
      CLOSE(IU)
      E = PROPS(1)
      ANU = PROPS(2)
      ALAM = E*ANU/((1.0D0 + ANU)*(1.0D0 - 2.0D0*ANU))
      AMU = 0.5D0*E/(1.0D0 + ANU)
      DO I = 1, NTENS
        DO J = 1, NTENS
          DDSDDE(I,J) = 0.0D0
        END DO
      END DO
      DO I = 1, NDI
        DO J = 1, NDI
          DDSDDE(I,J) = ALAM
        END DO
        DDSDDE(I,I) = ALAM + 2.0D0*AMU
      END DO
      DO I = NDI + 1, NTENS
        DDSDDE(I,I) = AMU
      END DO
      DO I = 1, NTENS
        DO J = 1, NTENS
          STRESS(I) = STRESS(I) + DDSDDE(I,J)*DSTRAN(J)
        END DO
      END DO
      RETURN
      END
