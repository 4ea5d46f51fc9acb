# Load and branch delay-slot routines for cpu_pipeline.c. Each returns its observation in $v0;
# the expected values follow from the R3000A pipeline rules in psx-spx "CPU Specifications".
        .set noreorder
        .set noat
        .text

# The instruction in a load's delay slot still sees the register's old value.
        .globl load_delay_sees_old
load_delay_sees_old:
        li      $t0, 0x1111
        lw      $t0, 0($a0)
        move    $v0, $t0
        jr      $ra
        nop

# One instruction later the loaded value has arrived.
        .globl load_delay_arrives
load_delay_arrives:
        li      $t0, 0x1111
        lw      $t0, 0($a0)
        nop
        jr      $ra
        move    $v0, $t0

# A write to the load's target in the delay slot wins over the load.
        .globl load_overwritten
load_overwritten:
        lw      $v0, 0($a0)
        li      $v0, 0x2222
        jr      $ra
        nop

# Two loads to one register back to back: the delay slot of the second sees neither's value
# only if the first was cancelled; the register ends with the second load's value.
        .globl load_twice
load_twice:
        li      $v0, 0x3333
        lw      $v0, 0($a0)
        lw      $v0, 4($a0)
        nop
        jr      $ra
        nop

# LWR then LWL back to back merge through the in-flight load: an unaligned word at a0+1.
        .globl unaligned_pair
unaligned_pair:
        li      $v0, 0
        lwr     $v0, 1($a0)
        lwl     $v0, 4($a0)
        nop
        jr      $ra
        nop

# MFC0 has a load delay too.
        .globl mfc0_delay_sees_old
mfc0_delay_sees_old:
        li      $v0, 0x4444
        mfc0    $v0, $15
        move    $v1, $v0
        jr      $ra
        move    $v0, $v1

# The delay slot of a taken branch executes; the instruction after it does not.
        .globl taken_branch_slot
taken_branch_slot:
        li      $v0, 0
        beq     $zero, $zero, 1f
        addiu   $v0, $v0, 5
        addiu   $v0, $v0, 0x50
1:      jr      $ra
        nop

# The delay slot of a branch not taken executes as well, then execution falls through.
        .globl untaken_branch_slot
untaken_branch_slot:
        li      $v0, 0
        bne     $zero, $zero, 1f
        addiu   $v0, $v0, 5
        addiu   $v0, $v0, 0x50
1:      jr      $ra
        nop

# A jump in a jump's delay slot: the first target's instruction runs once (as the second
# jump's delay slot), then execution continues at the second target.
        .globl jump_in_delay_slot
jump_in_delay_slot:
        li      $v0, 0
        j       1f
        j       2f
1:      addiu   $v0, $v0, 1
        addiu   $v0, $v0, 0x10
2:      addiu   $v0, $v0, 0x100
        jr      $ra
        nop

# JAL links the address after its delay slot; returns (link - address of the jal).
        .globl jal_link_offset
jal_link_offset:
        move    $t9, $ra
        jal     1f
        nop
1:      la      $t0, 1b
        jr      $t9
        subu    $v0, $ra, $t0

# BLTZAL links even when the branch is not taken; returns the link register minus the site.
        .globl bltzal_untaken_link
bltzal_untaken_link:
        move    $t9, $ra
        li      $t0, 1
        .globl bltzal_site
bltzal_site:
        bltzal  $t0, 1f
        nop
1:      la      $t1, bltzal_site
        jr      $t9
        subu    $v0, $ra, $t1
