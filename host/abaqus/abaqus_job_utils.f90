!> Abaqus/Standard environment utility routines for user code: GETJOBNAME and GETOUTDIR.
!>
!> Interfaces as documented by Abaqus ("Obtaining Abaqus environment information"): CALL GETJOBNAME(JOBNAME,
!> LENJOBNAME) and CALL GETOUTDIR(OUTDIR, LENOUTDIR), the character variable declared by the caller (the manual
!> recommends CHARACTER*256; user code found with the search tool also declares CHARACTER*64 names), the length
!> of the returned text in the integer. The text comes from the host's job state (module abaqus_host_state:
!> the deck's base name and the --out directory). A value longer than the caller's variable is truncated and the
!> length reports the truncated length, so JOBNAME(1:LENJOBNAME) is always valid; the rest is blank-filled
!> (user code often applies TRIM instead of the length).

!> GETJOBNAME: the job name (the deck's base name) and its length.
subroutine getjobname(jobname, lenjobname)
  use abaqus_host_state, only: abaqus_job_name
  implicit none
  character(len=*), intent(out) :: jobname     !< job name, blank-filled
  integer, intent(out) :: lenjobname           !< length of the name in jobname
  character(len=:), allocatable :: name

  name = abaqus_job_name()
  jobname = name
  lenjobname = min(len(name), len(jobname))
end subroutine getjobname

!> GETOUTDIR: the output directory of the job and its length.
subroutine getoutdir(outdir, lenoutdir)
  use abaqus_host_state, only: abaqus_output_dir
  implicit none
  character(len=*), intent(out) :: outdir      !< output directory, blank-filled
  integer, intent(out) :: lenoutdir            !< length of the directory name in outdir
  character(len=:), allocatable :: dir

  dir = abaqus_output_dir()
  outdir = dir
  lenoutdir = min(len(dir), len(outdir))
end subroutine getoutdir
