ConfigVersion 2.0
; JAria robot parameter file: p3at
; Pioneer 3-AT with the older H8 controller: same body and sonars as
; p3at-sh, positions in units of 0.465 mm.
; Format: "Keyword value ; comment", read by org.jaria.params.ArRobotParams.
; To adapt it to one robot, copy it to <robot name>.p in your parameter
; folder and change only what differs: that file is loaded last.

Section General settings
Class Pioneer            ; family of the robot
Subclass p3at            ; model name; also the name of this file
RobotRadius 500          ; mm; radius of the circle the robot sweeps when turning
RobotDiagonal 120        ; mm; half-height to the diagonal of the octagon
RobotWidth 505           ; mm; overall width
RobotLength 626          ; mm; overall length
RobotLengthFront 313     ; mm from the turning centre to the front (0 = half length)
RobotLengthRear 313      ; mm from the turning centre to the rear (0 = half length)
Holonomic true           ; can turn on the spot
MaxRVelocity 300         ; deg/s; hard limit on rotation
MaxVelocity 1200         ; mm/s; hard limit on translation
MaxLatVelocity 0         ; mm/s; sideways motion (none on a Pioneer)
HasMoveCommand true      ; firmware understands MOVE
RequestIOPackets false   ; ask for IO packets right after connecting
RequestEncoderPackets false ; ask for encoder packets right after connecting
SwitchToBaudRate 38400   ; serial speed to change to after connecting (0 = stay)

Section Conversion factors
AngleConvFactor 0.00153  ; rad per angle unit: 2 pi / 4096 = 0.0015340, kept to 5 decimals as ARIA does
DistConvFactor 0.465     ; mm per position unit
VelConvFactor 1.0        ; mm/s per velocity unit
RangeConvFactor 1.0      ; mm per sonar range unit
DiffConvFactor 0.0034    ; wheel speed difference to turn rate (old firmware only)
Vel2Divisor 20           ; VEL2 wheel speeds are in units of this many mm/s
GyroScaler 1.626         ; scale of the gyro rate readings

Section Accessories the robot has
TableSensingIR false     ; upward-looking table IRs fitted
NewTableSensingIR false  ; table IR states arrive in the IO packet
FrontBumpers false       ; front bump ring fitted
NumFrontBumpers 5        ; segments in the front ring
RearBumpers false        ; rear bump ring fitted
NumRearBumpers 5         ; segments in the rear ring

Section IR parameters
IRNum 0                  ; how many IR sensors

Section Movement control parameters
SettableVelMaxes true    ; TransVelMax / RotVelMax may be sent
TransVelMax 0            ; mm/s; 0 keeps the value in the robot FLASH
RotVelMax 0              ; deg/s; 0 keeps the value in the robot FLASH
SettableAccsDecs true    ; accelerations may be sent
TransAccel 0             ; mm/s2; 0 keeps the FLASH value
TransDecel 0             ; mm/s2; 0 keeps the FLASH value
RotAccel 0               ; deg/s2; 0 keeps the FLASH value
RotDecel 0               ; deg/s2; 0 keeps the FLASH value
HasLatVel false          ; can move sideways
LatVelMax 0              ; mm/s
LatAccel 0               ; mm/s2
LatDecel 0               ; mm/s2

Section GPS parameters
GPSPX -160               ; mm; antenna position, forward
GPSPY 120                ; mm; antenna position, left
GPSType novatel          ; receiver kind: standard, novatel or trimble
GPSPort COM2             ; computer port of the receiver
GPSBaud 9600             ; receiver speed

Section Compass parameters
CompassType robot        ; robot = TCM2 data in the SIP; serialTCM = on a computer port
CompassPort              ; computer port, only for serialTCM

Section Sonar parameters
SonarNum 16              ; how many sonar discs
; SonarUnit <number> <x mm> <y mm> <heading deg>, from the turning centre,
; x forward, y left, heading counter-clockwise from straight ahead
SonarUnit 0 147 136 90
SonarUnit 1 193 119 50
SonarUnit 2 227 79 30
SonarUnit 3 245 27 10
SonarUnit 4 245 -27 -10
SonarUnit 5 227 -79 -30
SonarUnit 6 193 -119 -50
SonarUnit 7 147 -136 -90
SonarUnit 8 -144 -136 -90
SonarUnit 9 -189 -119 -130
SonarUnit 10 -223 -79 -150
SonarUnit 11 -241 -27 -170
SonarUnit 12 -241 27 170
SonarUnit 13 -223 79 150
SonarUnit 14 -189 119 130
SonarUnit 15 -144 136 90

Section Laser parameters
LaserAutoConnect true    ; connect to this laser at start-up
LaserX 160               ; mm; forward of the turning centre
LaserY 0                 ; mm; left of the turning centre
LaserTh 0.0              ; deg; counter-clockwise rotation of the scanner
LaserZ 0                 ; mm above the floor (0 = unknown)
LaserFlipped false       ; mounted upside down
LaserType lms2xx         ; scanner model
LaserPortType serial     ; serial or tcp
LaserPort COM3           ; port name or address
LaserPowerControlled true ; serial line controls the laser power
LaserMaxRange 0          ; mm; 0 = the scanner's own maximum

Section PTZ 1 parameters
PTZAutoConnect true      ; connect to this pan/tilt unit at start-up
PTZType vcc4             ; camera mount model
PTZInverted false        ; mounted upside down
PTZSerialPort none       ; computer serial port, or none
PTZRobotAuxSerialPort 1  ; robot AUX port (1-3), or -1
PTZAddress none          ; network address, or none
PTZTCPPort 80            ; HTTP port for network cameras

Section Video 1 parameters
VideoAutoConnect true    ; open this video source at start-up
VideoType v4l            ; capture driver or camera model
VideoInverted false      ; flip the image (camera upside down)
VideoWidth -1            ; pixels; -1 = default
VideoHeight -1           ; pixels; -1 = default
VideoDeviceIndex -1      ; -1 = default
VideoDeviceName none     ; overrides VideoDeviceIndex
VideoChannel -1          ; input channel; -1 = default
VideoAddress none        ; network address, or none
VideoTCPPort 80          ; HTTP port for network cameras
