C     A user UMAT in the classic style (test deck_user_files): fixed form, implicit typing, the include file
C     named in lower case, a preprocessor block and messages to units 7 and 6 (Abaqus: JOB.msg, JOB.dat), its elasticity
C     matrix built by a helper in another file (elastic_helper.f90, or its object file). Small-strain isotropic
C     elasticity: PROPS(1) = E, PROPS(2) = nu. A branch never taken calls a routine no file defines: as in
C     Abaqus' link, that is an error only if it is ever called (lazy binding).
      SUBROUTINE UMAT(STRESS,STATEV,DDSDDE,SSE,SPD,SCD,
     1 RPL,DDSDDT,DRPLDE,DRPLDT,
     2 STRAN,DSTRAN,TIME,DTIME,TEMP,DTEMP,PREDEF,DPRED,CMNAME,
     3 NDI,NSHR,NTENS,NSTATV,PROPS,NPROPS,COORDS,DROT,PNEWDT,
     4 CELENT,DFGRD0,DFGRD1,NOEL,NPT,LAYER,KSPT,JSTEP,KINC)
      include 'aba_param.inc'
      CHARACTER*80 CMNAME
      DIMENSION STRESS(NTENS),STATEV(NSTATV),
     1 DDSDDE(NTENS,NTENS),DDSDDT(NTENS),DRPLDE(NTENS),
     2 STRAN(NTENS),DSTRAN(NTENS),TIME(2),PREDEF(1),DPRED(1),
     3 PROPS(NPROPS),COORDS(3),DROT(3,3),DFGRD0(3,3),DFGRD1(3,3),
     4 JSTEP(4)
      IF (NPROPS .GT. 99) CALL NOT_DEFINED_IN_ANY_FILE(PROPS)
      CALL ELASTIC_MATRIX(PROPS(1), PROPS(2), NDI, NTENS, DDSDDE)
      DO I = 1, NTENS
        DO J = 1, NTENS
          STRESS(I) = STRESS(I) + DDSDDE(I,J)*DSTRAN(J)
        END DO
      END DO
      DO I = 1, NTENS
        SSE = SSE + 0.5D0*STRESS(I)*DSTRAN(I)
      END DO
#ifdef ABQ_LNX86_64
      IF (NOEL.EQ.1 .AND. NPT.EQ.1 .AND. KINC.EQ.1) THEN
        WRITE(7,*) 'UMAT_FIXED: compiled for Linux, first call'
        WRITE(6,*) 'UMAT_FIXED: unit 6 of the first call'
      END IF
#else
      THIS LINE IS NOT FORTRAN: THE PREPROCESSOR MUST REMOVE IT
#endif
      RETURN
      END
