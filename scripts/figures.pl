#!/usr/bin/perl
# figures.pl FIGURES.tsv: rewrite the figures of README.md and docs/*.md in place from the
# "key<TAB>text" lines the tests wrote under `make figures` (tests/figures.h). Every marker
# <!--fig:KEY-->TEXT<!--/fig--> gets its key's text; a file is written only when it changes.
# Fails (exit 1) on a marker whose key no test produced, or a key produced with two texts.
use strict;
use warnings;

my $tsv = shift or die "usage: figures.pl FIGURES.tsv\n";
my %fig;
my $bad = 0;
open(my $in, '<', $tsv) or die "figures.pl: cannot open $tsv: $!\n";
while (my $l = <$in>) {
    chomp $l;
    my ($k, $t) = split /\t/, $l, 2;
    next unless defined $t;
    if (exists $fig{$k} && $fig{$k} ne $t) {
        print STDERR "figures.pl: $k produced as '$fig{$k}' and '$t' (by make test's and "
            . "make verify's runs? a figure that depends on the mode needs a key for each)\n";
        $bad = 1;
    }
    $fig{$k} = $t;
}
close $in;

my ($nmark, $nchanged, %used, %write) = (0, 0);
for my $f ('README.md', sort glob('docs/*.md')) {
    open(my $fh, '<', $f) or die "figures.pl: cannot open $f: $!\n";
    local $/;
    my $old = <$fh>;
    close $fh;
    my $new = $old;
    $new =~ s{(<!--fig:([a-z0-9_.\-]+)-->)(.*?)(<!--/fig-->)}{
        my ($o, $k, $t, $c) = ($1, $2, $3, $4);
        $nmark++;
        if (exists $fig{$k}) { $used{$k} = 1; "$o$fig{$k}$c" }
        else { print STDERR "figures.pl: $f: no test produced '$k'\n"; $bad = 1; "$o$t$c" }
    }ge;
    $write{$f} = $new if $new ne $old;
}
# all or nothing: no file is rewritten when a marker has no figure
for my $f ($bad ? () : sort keys %write) {
    open(my $out, '>', $f) or die "figures.pl: cannot write $f: $!\n";
    print $out $write{$f};
    close $out;
    $nchanged++;
    print "figures: rewrote $f\n";
}
my $nunused = grep { !$used{$_} } keys %fig;
printf "figures: %d markers, %d figures produced (%d not in a doc), %d files changed\n",
    $nmark, scalar(keys %fig), $nunused, $nchanged;
exit $bad;
