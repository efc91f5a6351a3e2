"""The manipulator arm: links from a Denavit-Hartenberg table (`arm`, `joint` lines) and a
two-finger gripper (`gripper`), each joint and the gripper moved by a servo. No RoBIOS group of its
own: the servo group answers SERVOSet for them, as for any servo (calls/servo.py, by the numbers of
the `joint` and `gripper` lines)."""
