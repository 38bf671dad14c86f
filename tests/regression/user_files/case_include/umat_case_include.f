C     A user UMAT written on Windows (test deck_user_files, case 7): it INCLUDEs 'PAST_NPROPS.INC' while the file
C     beside it is past_nprops.inc (Intel Fortran on Windows does not tell the cases apart; ldfcz copies it under the
C     name the source uses, with a warning). It also reads the PROPS after NPROPS, as a routine does whose deck gives
C     fewer constants than it reads: ldfcz passes zeros there (umat_props_pad), which it reports to JOB.msg.
C     Small-strain isotropic elasticity through elastic_helper.f90: PROPS(1) = E, PROPS(2) = nu.
      SUBROUTINE UMAT(STRESS,STATEV,DDSDDE,SSE,SPD,SCD,
     1 RPL,DDSDDT,DRPLDE,DRPLDT,
     2 STRAN,DSTRAN,TIME,DTIME,TEMP,DTEMP,PREDEF,DPRED,CMNAME,
     3 NDI,NSHR,NTENS,NSTATV,PROPS,NPROPS,COORDS,DROT,PNEWDT,
     4 CELENT,DFGRD0,DFGRD1,NOEL,NPT,LAYER,KSPT,JSTEP,KINC)
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'PAST_NPROPS.INC'
      CHARACTER*80 CMNAME
      DIMENSION STRESS(NTENS),STATEV(NSTATV),
     1 DDSDDE(NTENS,NTENS),DDSDDT(NTENS),DRPLDE(NTENS),
     2 STRAN(NTENS),DSTRAN(NTENS),TIME(2),PREDEF(1),DPRED(1),
     3 PROPS(*),COORDS(3),DROT(3,3),DFGRD0(3,3),DFGRD1(3,3),
     4 JSTEP(4)
      CALL ELASTIC_MATRIX(PROPS(1), PROPS(2), NDI, NTENS, DDSDDE)
      DO I = 1, NTENS
        DO J = 1, NTENS
          STRESS(I) = STRESS(I) + DDSDDE(I,J)*DSTRAN(J)
        END DO
      END DO
      PAST = 0.D0
      DO K = 1, NPAST
        PAST = PAST + ABS(PROPS(NPROPS + K))
      END DO
      IF (NOEL.EQ.1 .AND. NPT.EQ.1 .AND. KINC.EQ.1) THEN
        WRITE(7,'(A,I0,A,ES10.3)') 'PAST_NPROPS: sum of |PROPS(NPROPS+1:NPROPS+',
     1    NPAST, ')| = ', PAST
      END IF
      RETURN
      END
