"""Thrusters: a submarine's motors, each pushing along its own axis while under water. No RoBIOS
group of their own: the motor group drives them with MOTORDrive by the `thruster` lines' motor
numbers (calls/motor.py); they have no encoders and no speed control."""
